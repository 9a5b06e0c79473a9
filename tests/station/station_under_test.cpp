#include "tests/station/station_under_test.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <csignal>

#include "tests/daemon/daemon_rig.hpp"
#include "tests/ledger/ledger_shop.hpp"
#include "tests/station/left_batches.hpp"

namespace lastcut::daemon::testing {
namespace {

// The settings both rigs spell alike, into either rig's options (RigOptions or ShopOptions).
template <typename Options>
void apply_common(const StationSettings& settings, Options& options) {
  options.duplicate_policy = settings.duplicate_policy;
  options.batch_window_s = settings.window_s;
  if (!settings.hides) return;
  options.extra_paths = "hides = \"hides\"\n";
  options.extra_config =
      "[materials.leather]\nkind = \"hide\"\ncutter = \"cutter-1\"\npairs = \"any\"\nspacing_mm = 3\n"
      "rotation_step_deg = 90\n";
}

class SpoolStation : public StationUnderTest {
 public:
  SpoolStation(const std::string& name, const StationSettings& settings)
      : fault_(settings.cutter_fault), rig_(name, options(settings)) {}

  std::string start() override {
    if (std::string trouble = start_cutter(fault_); !trouble.empty()) return trouble;
    rig_.start_daemon();
    return ::testing::Test::HasFatalFailure() ? "lastcutd did not start: " + log() : "";
  }
  std::filesystem::path watch() const override { return rig_.watch(); }
  std::filesystem::path hides() const override { return rig_.root() / "hides"; }
  std::filesystem::path config_file() const override { return rig_.config_file(); }
  std::string log() const override { return read_text(rig_.daemon_log()); }
  std::vector<SeenJob> jobs() const override {
    std::vector<SeenJob> seen;
    for (const char* folder : {"work", "done", "failed", "held"}) {
      for (const auto& [id, state] : rig_.jobs(folder)) {
        std::string stage = state.value("stage", "");
        if (stage == "claimed") stage = "computing";
        if (stage == "cut") stage = "done";
        seen.push_back({id, state.value("scan", ""), stage, state.value("reason", ""), state.value("batch", "")});
      }
    }
    return seen;
  }
  std::string hide_state(const std::string& hide_id) const override {
    std::error_code error;
    for (std::filesystem::directory_iterator it(rig_.spool() / "batches", error), end; !error && it != end;
         it.increment(error)) {
      const auto batch = nlohmann::json::parse(read_text(it->path() / "batch.json"), nullptr, false);
      if (batch.is_discarded() || !batch.contains("hide") || batch["hide"].value("id", "") != hide_id) continue;
      const std::string stage = batch.value("stage", "");
      if (stage == "nesting") return batch.value("jobs", nlohmann::json::array()).empty() ? "loaded" : "nesting";
      if (stage == "empty" || stage == "abandoned") return "empty";
      return "used";  // queued, sending, cut, held: nested
    }
    return "";
  }
  std::string batch_state(const std::string& batch) const override {
    return batch_json(batch).value("stage", "");
  }
  std::string cut_file(const std::string& batch) const override {
    const std::string name = batch_json(batch).value("cut_file", "");
    return name.empty() ? "" : read_text(rig_.spool() / "batches" / batch / name);
  }
  void signal(int signal) override { rig_.daemon()->signal(signal); }
  int stop() override { return rig_.stop_daemon(); }
  void kill() override { rig_.kill_daemon(); }
  std::string restart() override {
    // The log is appended across runs: this run's "lastcutd ready" comes after what is there now.
    const std::size_t before = log().size();
    rig_.start_daemon();
    if (wait_until([&] { return log().find("lastcutd ready", before) != std::string::npos; }, 30)) return "";
    return "lastcutd did not start again: " + log().substr(before);
  }
  std::string start_cutter(const std::string& fault) override {
    stop_cutter();
    const auto run = rig_.root() / ("cutter-1-run-" + std::to_string(++runs_));
    std::string error;
    cutter_ = start_simulator("hpgl", rig_.root() / "cutter-1.tty", run, fault, run.string() + ".log", error);
    return cutter_ ? "" : error;
  }
  void stop_cutter() override {
    if (cutter_ && cutter_->running()) {
      cutter_->signal(SIGTERM);
      cutter_->wait(10);
    }
  }
  std::vector<std::string> received_per_run() const override {
    std::vector<std::string> runs;
    for (int run = 1; run <= runs_; ++run)
      runs.push_back(simulator_received("hpgl", rig_.root() / ("cutter-1-run-" + std::to_string(run))));
    return runs;
  }
  std::string leave_batch(LeftBatch kind, const std::string& scan, const std::string& cut_program) override {
    return leave_spool_batch(rig_.spool(), ++left_, kind, scan, cut_program);
  }

 private:
  static RigOptions options(const StationSettings& settings) {
    RigOptions options;
    apply_common(settings, options);
    options.batch_max_pieces = settings.max_pieces;
    return options;
  }
  nlohmann::json batch_json(const std::string& batch) const {
    if (batch.empty()) return nlohmann::json::object();
    const auto json = nlohmann::json::parse(read_text(rig_.spool() / "batches" / batch / "batch.json"), nullptr, false);
    return json.is_object() ? json : nlohmann::json::object();
  }
  // cutter-1 is this class's own simulator (not the rig's), one record folder per run; declared
  // before the rig, so that lastcutd is stopped before its cutter goes.
  std::unique_ptr<Process> cutter_;
  int runs_ = 0;
  int left_ = 0;  // batches left by leave_batch
  std::string fault_;
  mutable DaemonRig rig_;
};

class LedgerStation : public StationUnderTest {
 public:
  LedgerStation(const std::string& name, const StationSettings& settings)
      : fault_(settings.cutter_fault), shop_(name, options(settings)) {}

  std::string start() override {
    if (std::string trouble = shop_.start_services(); !trouble.empty()) return trouble;
    if (std::string trouble = shop_.start_cutter("cutter-1", fault_); !trouble.empty()) return trouble;
    return shop_.start_node(kNode);
  }
  std::filesystem::path watch() const override { return shop_.watch(kNode); }
  std::filesystem::path hides() const override { return shop_.node_dir(kNode) / "hides"; }
  std::filesystem::path config_file() const override { return shop_.config_file(kNode); }
  std::string log() const override { return read_text(shop_.log_file(kNode)); }
  std::vector<SeenJob> jobs() const override {
    std::vector<SeenJob> seen;
    for (const auto& row : shop_.rows("SELECT id, scan_name, state, coalesce(reason, ''), coalesce(batch_id::text, '')"
                                      " FROM jobs ORDER BY id")) {
      const std::string state = row[2] == "ready" ? "computing" : row[2];
      seen.push_back({row[0], row[1], state, row[3], row[4]});
    }
    return seen;
  }
  std::string hide_state(const std::string& hide_id) const override {
    return shop_.value("SELECT state FROM hides WHERE name = '" + hide_id + "'");
  }
  std::string batch_state(const std::string& batch) const override {
    return batch.empty() ? "" : shop_.value("SELECT state FROM batches WHERE id = " + batch);
  }
  std::string cut_file(const std::string& batch) const override {
    const std::string name = batch.empty() ? "" : shop_.value("SELECT cut_file FROM batches WHERE id = " + batch);
    return name.empty() ? "" : read_text(shop_.shared_dir() / name);
  }
  void signal(int signal) override { shop_.signal_node(kNode, signal); }
  int stop() override { return shop_.stop_node(kNode); }
  void kill() override { shop_.kill_node(kNode); }
  std::string restart() override { return shop_.start_node(kNode); }
  std::string start_cutter(const std::string& fault) override { return shop_.start_cutter("cutter-1", fault); }
  void stop_cutter() override { shop_.stop_cutter("cutter-1"); }
  std::vector<std::string> received_per_run() const override { return shop_.received_per_run("cutter-1"); }
  std::string leave_batch(LeftBatch kind, const std::string& scan, const std::string& cut_program) override {
    return leave_ledger_batch(shop_.url(), shop_.shared_dir(), kind, scan, cut_program);
  }

 private:
  static constexpr const char* kNode = "station-a";
  static ShopOptions options(const StationSettings& settings) {
    ShopOptions options;
    options.nodes = {{kNode, {"compute", "station"}}};
    options.cutters = {{"cutter-1", "hpgl", kNode}};
    apply_common(settings, options);
    options.max_pieces = settings.max_pieces;
    return options;
  }
  std::string fault_;
  mutable LedgerShop shop_;
};

}  // namespace

std::unique_ptr<StationUnderTest> StationUnderTest::make(StoreKind kind, const std::string& name,
                                                         const StationSettings& settings) {
  // A folder per store: CTest runs the two cases of a behaviour at the same time.
  if (kind == StoreKind::Spool) return std::make_unique<SpoolStation>(name + "-spool", settings);
  return std::make_unique<LedgerStation>(name + "-ledger", settings);
}

SeenJob StationUnderTest::job(const std::string& scan) const {
  SeenJob found;
  for (const SeenJob& seen : jobs())
    if (seen.scan == scan) found = seen;  // ids ascend with time in both stores: the newest stays
  return found;
}

int StationUnderTest::requeue(const std::string& job_id) const {
  const auto out = config_file().parent_path() / "requeue.txt";
  return run_command({binary("lastcut").string(), "requeue", job_id, "--config", config_file().string()}, out);
}

std::string StationUnderTest::status() const {
  const auto out = config_file().parent_path() / "status.txt";
  std::filesystem::remove(out);
  const int exit_status =
      run_command({binary("lastcut").string(), "status", "--config", config_file().string()}, out);
  const std::string text = read_text(out);
  EXPECT_EQ(exit_status, 0) << text;
  return text;
}

void StationUnderTest::drop_scan(const std::string& name, const std::string& tag, const std::string& ticket) const {
  const auto staging = config_file().parent_path() / "staging";
  std::filesystem::create_directories(staging);
  write_variant(small_last(40, "left", 7), staging / (tag + ".stl"), tag);
  drop_copy(tag, name, ticket);
}

void StationUnderTest::drop_copy(const std::string& tag, const std::string& as, const std::string& ticket) const {
  const auto staging = config_file().parent_path() / "staging";
  if (!ticket.empty())
    write_text(watch() / (std::filesystem::path(as).stem().string() + ".job.toml"), ticket);
  drop(staging / (tag + ".stl"), watch(), as);  // a copy: the same tag may be dropped again
}

void StationUnderTest::edit_config(const std::string& from, const std::string& to) const {
  std::string text = read_text(config_file());
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from << " not in " << text;
  text.replace(at, from.size(), to);
  write_text(config_file(), text);
}

}  // namespace lastcut::daemon::testing
