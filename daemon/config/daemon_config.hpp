#pragma once
// DaemonConfig: everything lastcutd reads from its one TOML file (config/lastcut.toml documents
// every key). Plain values, already validated by load_daemon_config(); units are in the names.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "daemon/config/ledger_config.hpp"
#include "drivers/cutter_settings.hpp"

namespace lastcut::daemon {

enum class WatchMode { Auto, Inotify, Poll };
// What to do with a scan whose bytes (SHA-256) equal an earlier job's scan.
enum class DuplicatePolicy { Skip, Process, Hold };

struct PathsConfig {
  std::filesystem::path watch_dir;     // where scans are dropped (the hot folder)
  std::filesystem::path spool_dir;     // work/, done/, failed/, held/ live here
  std::filesystem::path machines_dir;  // machine profiles (*.toml) for the toolpath module
};

struct WatchConfig {
  WatchMode mode = WatchMode::Auto;
  double poll_interval_s = 2.0;     // poll mode: how often the folder is listed
  double rescan_interval_s = 60.0;  // inotify mode: full listing as a safety net
  int stable_checks = 2;            // size and mtime unchanged this many checks in a row
  double stable_interval_s = 1.0;   // time between two stability checks
  double incomplete_grace_s = 60;   // a stable file that still looks cut off is taken (and failed) after this
};

struct JobsConfig {
  DuplicatePolicy duplicate_policy = DuplicatePolicy::Skip;
  int max_attempts = 3;           // computing restarted this often (crash, hang) before failed/
  double compute_timeout_s = 600; // a computation longer than this is a stuck stage (watchdog)
  std::string default_material;   // key into materials
  std::string default_cutter;     // key into cutters
  double default_allowance_mm = 0;  // lasting allowance when the sidecar gives none
  double max_hole_across_mm = 30;   // scan holes up to this size across are closed, larger ones fail the job
  // Per-edge allowances and balance notch spacings when the sidecar gives none (0 = none/off);
  // any non-zero per-edge default makes molds per-edge (docs/mold-allowances.md).
  double default_lasting_mm = 0, default_seam_mm = 0, default_top_mm = 0;
  double default_seam_notch_spacing_mm = 0, default_feather_notch_spacing_mm = 0;
  int compute_workers = 1;          // scans computed at the same time
  double stop_grace_s = 60;         // on SIGTERM, a cut in progress may finish this long, then it is held
};

struct BatchConfig {
  double window_s = 0;  // collect molds per material and cutter this long before nesting (0: nest each job alone)
  int max_pieces = 0;   // ... or until this many pieces wait (0: no piece limit)
  double nest_time_s = 10;  // time the nester may spend improving one batch's layout
};

// A rectangular sheet or hide blank the molds are nested on.
struct MaterialConfig {
  double width_mm = 0;
  double length_mm = 0;
  double spacing_mm = 2;
  int rotation_step_deg = 90;  // allowed rotations: multiples of this (360: none)
};

// One cutter: how to reach it and talk to it (the driver's own settings type, read key for key
// from the table) and what the daemon adds around it.
struct CutterSection {
  drivers::CutterSettings link;
  std::string machine;           // machine profile name (paths.machines/<machine>.toml) or path
  double retry_interval_s = 30;  // cutter unreachable: wait this long before trying again
};

// Jobs whose sidecar names reference patterns: each mold is compared with its pattern
// (docs/compare.md); a corner farther off than this holds the job for review instead of cutting it.
struct ReviewConfig {
  double corner_tolerance_mm = 2.0;  // the thesis's permissible error at the corners
};

struct LogConfig {
  std::string level = "info";  // trace | debug | info | warn | error
};

struct DaemonConfig {
  PathsConfig paths;
  WatchConfig watch;
  JobsConfig jobs;
  BatchConfig batch;
  std::map<std::string, MaterialConfig> materials;
  std::map<std::string, CutterSection> cutters;
  ReviewConfig review;
  LogConfig log;
  std::optional<LedgerConfig> ledger;  // [ledger]: several nodes share one PostgreSQL job ledger
};

std::string to_string(DuplicatePolicy policy);
std::string to_string(WatchMode mode);

}  // namespace lastcut::daemon
