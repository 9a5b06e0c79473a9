// Validation of the daemon configuration: each table is read through a TableReader (table_reader.hpp) that
// remembers which keys it consumed, so every key nobody asked for is reported as unknown
// with its path and line (a typo must not silently fall back to a default).
#include "daemon/config/config_loader.hpp"

#include "daemon/config/ledger_config_reader.hpp"
#include "daemon/config/table_reader.hpp"
#include "daemon/config/web_config_reader.hpp"

#include <optional>
#include <set>
#include <sstream>
#include <vector>

#include <unistd.h>

#include <toml++/toml.h>

#include "daemon/config/mqtt_url.hpp"

namespace lastcut::daemon {
namespace {

void read_paths(TableReader& root, const std::filesystem::path& base, DaemonConfig& config,
                std::vector<std::string>& errors) {
  const toml::table* table = root.subtable("paths", true);
  if (!table) return;
  TableReader paths(*table, "paths", errors);
  std::string watch, spool, machines, hides, hide_stock, styles;
  paths.text("watch", watch, true);
  paths.text("spool", spool, true);
  paths.text("machines", machines, true);
  paths.text("hides", hides);
  paths.text("hide_stock", hide_stock);
  paths.text("styles", styles);
  paths.reject_unknown();
  if (!hides.empty()) config.paths.hides_dir = resolve(base, hides);
  if (!hide_stock.empty()) config.paths.hide_stock_dir = resolve(base, hide_stock);
  if (!styles.empty()) config.paths.styles_dir = resolve(base, styles);
  if (!watch.empty()) config.paths.watch_dir = resolve(base, watch);
  if (!spool.empty()) config.paths.spool_dir = resolve(base, spool);
  if (!machines.empty()) config.paths.machines_dir = resolve(base, machines);
}

void read_watch(TableReader& root, DaemonConfig& config, std::vector<std::string>& errors) {
  const toml::table* table = root.subtable("watch", false);
  if (!table) return;
  TableReader watch(*table, "watch", errors);
  std::string mode = "auto";
  watch.text("mode", mode);
  if (mode == "auto") config.watch.mode = WatchMode::Auto;
  else if (mode == "inotify") config.watch.mode = WatchMode::Inotify;
  else if (mode == "poll") config.watch.mode = WatchMode::Poll;
  else errors.push_back("watch.mode: \"" + mode + "\" is not one of auto, inotify, poll");
  watch.number("poll_interval_s", config.watch.poll_interval_s, 0.05, 3600);
  watch.number("rescan_interval_s", config.watch.rescan_interval_s, 0.1, 86400);
  watch.integer("stable_checks", config.watch.stable_checks, 1, 100);
  watch.number("stable_interval_s", config.watch.stable_interval_s, 0.01, 600);
  watch.number("incomplete_grace_s", config.watch.incomplete_grace_s, 0, 86400);
  watch.reject_unknown();
}

void read_jobs(TableReader& root, DaemonConfig& config, std::vector<std::string>& errors) {
  const toml::table* table = root.subtable("jobs", true);
  if (!table) return;
  TableReader jobs(*table, "jobs", errors);
  std::string policy = "skip";
  jobs.text("duplicate_policy", policy);
  if (policy == "skip") config.jobs.duplicate_policy = DuplicatePolicy::Skip;
  else if (policy == "process") config.jobs.duplicate_policy = DuplicatePolicy::Process;
  else if (policy == "hold") config.jobs.duplicate_policy = DuplicatePolicy::Hold;
  else errors.push_back("jobs.duplicate_policy: \"" + policy + "\" is not one of skip, process, hold");
  jobs.integer("max_attempts", config.jobs.max_attempts, 1, 100);
  jobs.number("compute_timeout_s", config.jobs.compute_timeout_s, 1, 86400);
  jobs.text("default_material", config.jobs.default_material, true);
  jobs.text("default_cutter", config.jobs.default_cutter, true);
  jobs.number("default_allowance_mm", config.jobs.default_allowance_mm, 0, 50);
  jobs.number("max_hole_across_mm", config.jobs.max_hole_across_mm, 0, 100);
  jobs.number("default_lasting_mm", config.jobs.default_lasting_mm, 0, 50);
  jobs.number("default_seam_mm", config.jobs.default_seam_mm, 0, 50);
  jobs.number("default_top_mm", config.jobs.default_top_mm, 0, 50);
  jobs.number("default_seam_notch_spacing_mm", config.jobs.default_seam_notch_spacing_mm, 0, 500);
  jobs.number("default_feather_notch_spacing_mm", config.jobs.default_feather_notch_spacing_mm, 0, 500);
  for (auto [key, value] : {std::pair{"default_seam_notch_spacing_mm", config.jobs.default_seam_notch_spacing_mm},
                            std::pair{"default_feather_notch_spacing_mm", config.jobs.default_feather_notch_spacing_mm}})
    if (value > 0 && value < 5) errors.push_back(std::string("jobs.") + key + ": must be 0 (off) or from 5 to 500");
  jobs.boolean("draw_sew_lines", config.jobs.draw_sew_lines);
  jobs.integer("compute_workers", config.jobs.compute_workers, 1, 64);
  jobs.number("stop_grace_s", config.jobs.stop_grace_s, 0, 3600);
  jobs.reject_unknown();
}

void read_batch(TableReader& root, DaemonConfig& config, std::vector<std::string>& errors) {
  const toml::table* table = root.subtable("batch", false);
  if (!table) return;
  TableReader batch(*table, "batch", errors);
  batch.number("window_s", config.batch.window_s, 0, 86400);
  batch.integer("max_pieces", config.batch.max_pieces, 0, 10000);
  batch.number("nest_time_s", config.batch.nest_time_s, 0.05, 3600);
  batch.reject_unknown();
}

void read_materials(TableReader& root, DaemonConfig& config, std::vector<std::string>& errors) {
  const toml::table* table = root.subtable("materials", true);
  if (!table) return;
  for (auto&& [key, value] : *table) {
    const std::string name(key.str());
    const std::string path = "materials." + name;
    if (!value.is_table()) {
      errors.push_back(where(path, value) + ": must be a table [" + path + "]");
      continue;
    }
    TableReader reader(*value.as_table(), path, errors);
    MaterialConfig material;
    std::string kind = "strip";
    reader.text("kind", kind);
    if (kind != "strip" && kind != "hide") errors.push_back(path + ".kind: \"" + kind + "\" is not strip or hide");
    const bool hide = kind == "hide";
    material.kind = hide ? MaterialKind::Hide : MaterialKind::Strip;
    if (!hide) {
      reader.number("width_mm", material.width_mm, 10, 100000, true);
      reader.number("length_mm", material.length_mm, 10, 100000, true);
    } else {
      std::string pairs = "same_hide";
      reader.text("pairs", pairs);
      reader.integer("min_quality", material.min_quality, 0, 1000);
      reader.integer("toe_min_quality", material.toe_min_quality, 0, 1000);
      reader.number("toe_fraction", material.toe_fraction, 0.05, 1);
      reader.number("grain_tolerance_deg", material.grain_tolerance_deg, 0, 90);
      reader.boolean("pieces_side_by_side", material.pieces_side_by_side);
      reader.boolean("mirror_pairs", material.mirror_pairs);
      if (pairs != "same_hide" && pairs != "any") errors.push_back(path + ".pairs: \"" + pairs + "\" is not same_hide or any");
      material.pairs_same_hide = pairs == "same_hide";
    }
    reader.text("cutter", material.cutter);
    reader.number("spacing_mm", material.spacing_mm, 0, 100);
    reader.integer("rotation_step_deg", material.rotation_step_deg, 1, 360);
    reader.reject_unknown();
    if (360 % material.rotation_step_deg != 0) errors.push_back(path + ".rotation_step_deg: must divide 360");
    config.materials[name] = material;
  }
  if (config.materials.empty()) errors.push_back("materials: at least one material is needed");
}

// The TOML value of a cutter option, converted to the option's kind; type mistakes are reported
// here, value mistakes by drivers::set_cutter_option (the same words `lastcut send` uses).
std::optional<drivers::OptionValue> option_value(const drivers::CutterOption& option, const toml::node& node,
                                                 const std::string& key_path, std::vector<std::string>& errors) {
  using drivers::OptionKind;
  const auto refuse = [&](const toml::node& at, const std::string& why) {
    errors.push_back(where(key_path, at) + ": " + why);
    return std::nullopt;
  };
  switch (option.kind) {
    case OptionKind::Text:
    case OptionKind::Choice:
      if (!node.is_string()) return refuse(node, "must be a text in quotes");
      return *node.value<std::string>();
    case OptionKind::Integer:
      if (!node.is_integer()) return refuse(node, "must be a whole number");
      return static_cast<long long>(*node.value<int64_t>());
    case OptionKind::Number:
      if (!node.is_number()) return refuse(node, "must be a number");
      return *node.value<double>();
    case OptionKind::Switch:
      if (!node.is_boolean()) return refuse(node, "must be true or false");
      return *node.value<bool>();
    case OptionKind::Integers: {
      const toml::array* list = node.as_array();
      if (!list) return refuse(node, "must be a list of whole numbers, e.g. [20, 22]");
      std::vector<long long> values;
      for (const toml::node& item : *list) {
        if (!item.is_integer()) return refuse(item, "each entry must be a whole number");
        values.push_back(*item.value<int64_t>());
      }
      return values;
    }
    case OptionKind::Texts: {
      const toml::array* list = node.as_array();
      if (!list) return refuse(node, "must be a list of texts in quotes");
      std::vector<std::string> values;
      for (const toml::node& item : *list) {
        if (!item.is_string()) return refuse(item, "each entry must be a text in quotes");
        values.push_back(*item.value<std::string>());
      }
      return values;
    }
  }
  return std::nullopt;
}

void read_cutters(TableReader& root, const std::filesystem::path& base, DaemonConfig& config,
                  std::vector<std::string>& errors) {
  const toml::table* table = root.subtable("cutters", true);
  if (!table) return;
  for (auto&& [key, value] : *table) {
    const std::string name(key.str());
    const std::string path = "cutters." + name;
    if (!value.is_table()) {
      errors.push_back(where(path, value) + ": must be a table [" + path + "]");
      continue;
    }
    TableReader reader(*value.as_table(), path, errors);
    CutterSection cutter;
    drivers::CutterSettings& link = cutter.link;
    for (const drivers::CutterOption& option : drivers::cutter_options()) {
      const std::string option_key(option.key);
      const toml::node* found = reader.node(option_key);
      if (!found) continue;
      if (auto read = option_value(option, *found, reader.key_path(option_key), errors)) {
        if (std::string problem = drivers::set_cutter_option(link, option, *read); !problem.empty()) {
          errors.push_back(where(reader.key_path(option_key), *found) + ": " + problem);
        }
      }
    }
    reader.text("machine", cutter.machine, true);
    reader.number("retry_interval_s", cutter.retry_interval_s, 0.1, 86400);
    reader.reject_unknown();
    if (link.protocol.empty()) errors.push_back(path + ".protocol: missing (required)");
    if (link.protocol == "modbus" && link.modbus.empty()) errors.push_back(path + ".modbus: missing (required)");
    if (!link.protocol.empty() && link.protocol != "modbus" && link.port.empty()) {
      errors.push_back(path + ".port: missing (required)");
    }
    if (!link.modbus_map.empty()) link.modbus_map = resolve(base, link.modbus_map).string();
    for (const std::string* address : {&link.port, &link.modbus}) {
      const bool tcp = address->rfind("tcp://", 0) == 0;
      if (tcp && address->rfind("tcp://127.0.0.1:", 0) != 0 && address->rfind("tcp://localhost:", 0) != 0) {
        errors.push_back(path + ": \"" + *address + "\": network cutters are reached through a gateway on 127.0.0.1");
      }
    }
    // A relative device path (a simulator's pty link) is relative to this file, like the folders.
    const bool device_path = !link.port.empty() && link.port.find("://") == std::string::npos &&
                             link.port.rfind("usb:", 0) != 0;
    if (device_path) link.port = resolve(base, link.port).string();
    config.cutters[name] = cutter;
  }
  if (config.cutters.empty()) errors.push_back("cutters: at least one cutter is needed");
}

void read_review(TableReader& root, DaemonConfig& config, std::vector<std::string>& errors) {
  const toml::table* table = root.subtable("review", false);
  if (!table) return;
  TableReader review(*table, "review", errors);
  review.number("corner_tolerance_mm", config.review.corner_tolerance_mm, 0, 100);
  review.reject_unknown();
}

// [quality]: the mold quality gate's limits (engine/scan/mold_quality_limits.hpp). The ranges keep
// an operator from switching the gate off by a typo: a limit that lets everything through is refused.
void read_quality(TableReader& root, DaemonConfig& config, std::vector<std::string>& errors) {
  const toml::table* table = root.subtable("quality", false);
  if (!table) return;
  TableReader quality(*table, "quality", errors);
  MoldQualityLimits& limits = config.quality;
  quality.number("max_d_angle", limits.max_D_angle, 2.0, 10.0);
  quality.number("max_d_area", limits.max_D_area, 2.0, 10.0);
  quality.number("max_stretch", limits.max_stretch, 1.0, 100.0);
  quality.number("max_p95_stretch", limits.max_p95_stretch, 1.0, 100.0);
  quality.boolean("require_converged", limits.require_converged);
  quality.number("max_length_excess_pct", limits.max_length_excess_pct, 0.0, 100.0);
  quality.reject_unknown();
}

void read_log(TableReader& root, DaemonConfig& config, std::vector<std::string>& errors) {
  const toml::table* table = root.subtable("log", false);
  if (!table) return;
  TableReader log(*table, "log", errors);
  log.text("level", config.log.level);
  log.reject_unknown();
  const std::set<std::string> levels{"trace", "debug", "info", "warn", "error"};
  if (!levels.count(config.log.level)) {
    errors.push_back("log.level: \"" + config.log.level + "\" is not one of trace, debug, info, warn, error");
  }
}

void read_status(TableReader& root, const std::filesystem::path& base, DaemonConfig& config,
                 std::vector<std::string>& errors) {
  const toml::table* table = root.subtable("status", false);
  if (!table) return;
  StatusConfig& status = config.status;
  status.enabled = true;
  TableReader reader(*table, "status", errors);
  reader.text("mqtt_url", status.mqtt_url, true);
  char host[256] = {};
  if (::gethostname(host, sizeof host - 1) == 0) status.station = host;
  reader.text("station", status.station);
  reader.text("topic_prefix", status.topic_prefix);
  reader.text("username", status.username);
  reader.text("password", status.password);
  reader.text("ca_file", status.ca_file);
  reader.integer("keepalive_s", status.keepalive_s, 5, 3600);
  reader.integer("queue_limit", status.queue_limit, 1, 1000000);
  reader.reject_unknown();
  if (!status.mqtt_url.empty()) {
    std::string why;
    if (auto address = parse_mqtt_url(status.mqtt_url, why)) {
      status.host = address->host;
      status.port = address->port;
      status.tls = address->tls;
    } else {
      errors.push_back("status.mqtt_url: \"" + status.mqtt_url + "\" " + why);
    }
  }
  if (std::string problem = topic_level_problem(status.station); !problem.empty()) {
    errors.push_back("status.station: \"" + status.station + "\" " + problem);
  }
  if (status.topic_prefix.empty() || status.topic_prefix.find_first_of("+#") != std::string::npos ||
      status.topic_prefix.front() == '/' || status.topic_prefix.back() == '/') {
    errors.push_back("status.topic_prefix: \"" + status.topic_prefix +
                     "\" must be non-empty, without + or # and without a leading or trailing /");
  }
  if (!status.ca_file.empty() && !status.tls) errors.push_back("status.ca_file: only used with an mqtts:// URL");
  if (!status.ca_file.empty()) status.ca_file = resolve(base, status.ca_file).string();
  for (const auto& [name, cutter] : config.cutters) {
    if (std::string problem = topic_level_problem(name); !problem.empty()) {
      errors.push_back("cutters." + name + ": a cutter name in MQTT topics " + problem);
    }
  }
}

void cross_check(DaemonConfig& config, std::vector<std::string>& errors) {
  if (!config.jobs.default_material.empty() && !config.materials.count(config.jobs.default_material)) {
    errors.push_back("jobs.default_material: \"" + config.jobs.default_material + "\" is not a [materials.*] table");
  }
  if (!config.jobs.default_cutter.empty() && !config.cutters.count(config.jobs.default_cutter)) {
    errors.push_back("jobs.default_cutter: \"" + config.jobs.default_cutter + "\" is not a [cutters.*] table");
  }
  for (const auto& [name, material] : config.materials) {
    if (!material.cutter.empty() && !config.cutters.count(material.cutter))
      errors.push_back("materials." + name + ".cutter: \"" + material.cutter + "\" is not a [cutters.*] table");
    if (material.kind == MaterialKind::Hide && config.paths.hides_dir.empty())
      errors.push_back("materials." + name + ": kind = \"hide\" needs paths.hides (the folder hide files are dropped in)");
  }
  if (!config.paths.hides_dir.empty() &&
      (config.paths.hides_dir == config.paths.watch_dir || config.paths.hides_dir == config.paths.spool_dir)) {
    errors.push_back("paths.hides: must be a folder of its own, not the watch or spool folder");
  }
  if (!config.paths.watch_dir.empty() && config.paths.watch_dir == config.paths.spool_dir) {
    errors.push_back("paths.watch: must not be the spool folder itself (use a folder such as spool/incoming)");
  }
  if (config.ledger) {
    for (const std::string& cutter : config.ledger->cutters)
      if (!config.cutters.count(cutter)) errors.push_back("ledger.cutters: \"" + cutter + "\" is not a [cutters.*] table");
  }
}

}  // namespace

std::string to_string(DuplicatePolicy policy) {
  switch (policy) {
    case DuplicatePolicy::Skip: return "skip";
    case DuplicatePolicy::Process: return "process";
    case DuplicatePolicy::Hold: return "hold";
  }
  return "?";
}

std::string to_string(WatchMode mode) {
  switch (mode) {
    case WatchMode::Auto: return "auto";
    case WatchMode::Inotify: return "inotify";
    case WatchMode::Poll: return "poll";
  }
  return "?";
}

ConfigLoadResult load_daemon_config(const std::filesystem::path& file) {
  ConfigLoadResult result;
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error& error) {
    std::ostringstream out;
    out << file.string() << " line " << error.source().begin.line << ": " << error.description();
    result.error = out.str();
    return result;
  }
  std::vector<std::string> errors;
  DaemonConfig config;
  const std::filesystem::path base = std::filesystem::absolute(file).parent_path();
  {
    TableReader reader(root, "", errors);
    read_paths(reader, base, config, errors);
    read_watch(reader, config, errors);
    read_jobs(reader, config, errors);
    read_batch(reader, config, errors);
    read_materials(reader, config, errors);
    read_cutters(reader, base, config, errors);
    read_review(reader, config, errors);
    read_quality(reader, config, errors);
    read_log(reader, config, errors);
    read_status(reader, base, config, errors);
    if (const toml::table* ledger = reader.subtable("ledger", false)) read_ledger_table(*ledger, base, config.ledger, errors);
    if (const toml::table* web = reader.subtable("web", false)) read_web_table(*web, base, config.web, errors);
    reader.reject_unknown();
  }
  cross_check(config, errors);
  if (!errors.empty()) {
    std::ostringstream out;
    for (std::size_t i = 0; i < errors.size(); ++i) out << (i ? "\n" : "") << file.string() << ": " << errors[i];
    result.error = out.str();
    return result;
  }
  result.config = std::move(config);
  return result;
}

}  // namespace lastcut::daemon
