// A multi-station shop of real lastcutd nodes for tests (see ledger_shop.hpp).
#include "tests/ledger/ledger_shop.hpp"
#include "tests/support/loopback_port.hpp"

#include <csignal>
#include <stdexcept>

#include <pqxx/pqxx>

namespace lastcut::daemon::testing {
namespace {

std::string toml_list(const std::vector<std::string>& items) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", \"" : "\"") + items[i] + "\"";
  return out + "]";
}

std::string tail(const std::string& text, std::size_t chars) {
  return text.size() > chars ? "..." + text.substr(text.size() - chars) : text;
}

}  // namespace

LedgerShop::LedgerShop(const std::string& name, ShopOptions options)
    : root_(scratch_folder(name)), options_(std::move(options)) {
  std::filesystem::create_directories(shared_dir());
  broker_ = std::make_unique<lastcut::test::MosquittoBroker>(root_ / "broker");
  for (const ShopNode& node : options_.nodes) {
    std::filesystem::create_directories(watch(node.name));
    std::filesystem::create_directories(spool(node.name));
  }
}

LedgerShop::~LedgerShop() {
  for (auto& [name, process] : nodes_) {
    if (process && process->running()) {
      process->signal(SIGTERM);
      process->wait(30);
    }
  }
  for (const auto& [name, process] : simulators_) stop_cutter(name);
}

std::string LedgerShop::start_services() {
  if (std::string failed = postgres_.start(); !failed.empty()) return "PostgreSQL: " + failed;
  std::string error;
  url_ = postgres_.create_database("lastcut", error);
  if (url_.empty()) return error;
  if (std::string failed = broker_->start(); !failed.empty()) return "mosquitto: " + failed;
  for (const ShopNode& node : options_.nodes) {
    if (!options_.web_token.empty()) web_ports_[node.name] = lastcut::test::free_loopback_port();
    write_text(config_file(node.name), node_config(node));
  }
  return "";
}

const ShopCutter& LedgerShop::cutter(const std::string& name) const {
  for (const ShopCutter& c : options_.cutters)
    if (c.name == name) return c;
  throw std::invalid_argument("no cutter " + name + " in this shop");
}

std::string LedgerShop::node_config(const ShopNode& node) const {
  std::string toml = "[paths]\nwatch = \"incoming\"\nspool = \"spool\"\nmachines = \"" +
                     (std::filesystem::path(LASTCUT_SOURCE_DIR) / "config/machines").string() + "\"\n" +
                     options_.extra_paths +
                     "[watch]\nmode = \"inotify\"\nrescan_interval_s = 2\nstable_checks = 2\n"
                     "stable_interval_s = 0.1\nincomplete_grace_s = 0.5\n"
                     "[jobs]\nduplicate_policy = \"" + options_.duplicate_policy + "\"\ndefault_material = \"calf\"\ndefault_cutter = \"" + options_.cutters.front().name + "\"\n"
                     "stop_grace_s = 20\n"
                     "[batch]\nnest_time_s = 0.3\nwindow_s = " + std::to_string(options_.batch_window_s) +
                     "\nmax_pieces = " + std::to_string(options_.max_pieces) + "\n"
                     "[materials.calf]\nwidth_mm = 800\nlength_mm = 1200\nspacing_mm = 3\n" +
                     options_.extra_config;
  std::vector<std::string> cabled;
  for (const ShopCutter& c : options_.cutters) {
    const bool here = c.station == node.name;
    if (here) cabled.push_back(c.name);
    const std::string port = (here ? root_ / (c.name + ".tty") : node_dir(node.name) / ("not-cabled-" + c.name)).string();
    toml += "[cutters." + c.name + "]\nprotocol = \"" + c.protocol + "\"\nport = \"" + port + "\"\n" +
            "timeout_s = " + std::to_string(c.timeout_s) + "\nretry_interval_s = 0.5\n" +
            (c.protocol == "grbl" ? "machine = \"grbl-drag-knife\"\n" : "flow = \"xonxoff\"\nmachine = \"hpgl-pen-plotter\"\n");
  }
  toml += "[ledger]\nurl = \"" + url_ + "\"\nnode = \"" + node.name + "\"\nroles = " + toml_list(node.roles) +
          "\nshared_dir = \"" + shared_dir().string() + "\"\nlease_s = " + std::to_string(options_.lease_s) +
          "\nheartbeat_s = " + std::to_string(options_.heartbeat_s) + "\n";
  if (!cabled.empty()) toml += "cutters = " + toml_list(cabled) + "\n";
  toml += "[status]\nmqtt_url = \"" + broker_->url() + "\"\nstation = \"" + node.name + "\"\nkeepalive_s = 5\n";
  if (!options_.web_token.empty()) {
    toml += "[web]\nlisten = \"127.0.0.1:" + std::to_string(web_ports_.at(node.name)) + "\"\nassets = \"" +
            (std::filesystem::path(LASTCUT_SOURCE_DIR) / "daemon/web/assets").string() + "\"\n[web.tokens]\nshop = \"" +
            options_.web_token + "\"\n";
  }
  return toml;
}

std::string LedgerShop::log_tails(std::size_t chars) const {
  std::string out;
  for (const ShopNode& node : options_.nodes) {
    out += "\n--- " + node.name + " log:\n" + tail(read_text(log_file(node.name)), chars);
  }
  return out;
}

std::string LedgerShop::start_cutter(const std::string& name, const std::string& fault) {
  const ShopCutter& c = cutter(name);
  stop_cutter(name);
  const int run = ++runs_[name];
  const std::string tag = name + "-" + std::to_string(run);
  std::string error;
  simulators_[name] = start_simulator(c.protocol, root_ / (name + ".tty"), root_ / ("record-" + tag), fault,
                                      root_ / ("sim-" + tag + ".log"), error);
  return simulators_[name] ? "" : error;
}

void LedgerShop::stop_cutter(const std::string& name) {
  auto it = simulators_.find(name);
  if (it == simulators_.end() || !it->second) return;
  if (it->second->running()) {
    it->second->signal(SIGTERM);
    it->second->wait(10);
  }
  it->second.reset();
}

std::vector<std::string> LedgerShop::received_per_run(const std::string& name) const {
  std::vector<std::string> out;
  const auto runs = runs_.find(name);
  for (int run = 1; runs != runs_.end() && run <= runs->second; ++run) {
    out.push_back(simulator_received(cutter(name).protocol, root_ / ("record-" + name + "-" + std::to_string(run))));
  }
  return out;
}

std::string LedgerShop::received(const std::string& name) const {
  std::string all;
  for (const std::string& run : received_per_run(name)) all += run;
  return all;
}

std::string LedgerShop::start_node(const std::string& node) {
  const std::size_t before = read_text(log_file(node)).size();
  nodes_[node] = std::make_unique<Process>(
      std::vector<std::string>{binary("lastcutd").string(), "--config", config_file(node).string()}, log_file(node));
  const auto ready = [&] {
    const std::string log = read_text(log_file(node));
    return log.size() > before && log.find("lastcutd ready", before) != std::string::npos;
  };
  wait_until([&] { return ready() || !nodes_[node]->running(); }, 30);
  if (ready()) return "";
  return node + " not ready after 30 s" + (nodes_[node]->running() ? "" : " (exited)") + ": " +
         tail(read_text(log_file(node)).substr(before), 4000);
}

void LedgerShop::signal_node(const std::string& node, int signal) {
  if (auto it = nodes_.find(node); it != nodes_.end() && it->second) it->second->signal(signal);
}

void LedgerShop::kill_node(const std::string& node) {
  auto& process = nodes_.at(node);
  process->signal(SIGKILL);
  process->wait(10);
}

int LedgerShop::stop_node(const std::string& node, double timeout_s) {
  auto& process = nodes_.at(node);
  process->signal(SIGTERM);
  return process->wait(timeout_s);
}

bool LedgerShop::node_running(const std::string& node) {
  auto it = nodes_.find(node);
  return it != nodes_.end() && it->second && it->second->running();
}

std::vector<std::vector<std::string>> LedgerShop::rows(const std::string& sql) const {
  pqxx::connection connection(url_);
  pqxx::read_transaction tx(connection);
  std::vector<std::vector<std::string>> out;
  for (const pqxx::row& row : tx.exec(sql)) {
    std::vector<std::string> values;
    for (const pqxx::field& field : row) values.push_back(field.is_null() ? "" : field.as<std::string>());
    out.push_back(std::move(values));
  }
  return out;
}

std::string LedgerShop::value(const std::string& sql) const {
  try {
    const auto result = rows(sql);
    return result.empty() || result[0].empty() ? "" : result[0][0];
  } catch (const pqxx::broken_connection&) {
    return "";  // the server is restarting; a mistake in the query still throws
  }
}

long long LedgerShop::count(const std::string& sql) const {
  const std::string text = value(sql);
  return text.empty() ? -1 : std::stoll(text);
}

}  // namespace lastcut::daemon::testing
