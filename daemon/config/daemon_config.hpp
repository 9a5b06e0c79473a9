#pragma once
// DaemonConfig: everything lastcutd reads from its one TOML file (config/lastcut.toml documents
// every key). Plain values, already validated by load_daemon_config(); units are in the names.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "daemon/config/ledger_config.hpp"
#include "daemon/config/web_config.hpp"
#include "drivers/cutter_settings.hpp"
#include "engine/scan/mold_quality_limits.hpp"

namespace lastcut::daemon {

enum class WatchMode { Auto, Inotify, Poll };
// What to do with a scan whose bytes (SHA-256) equal an earlier job's scan.
enum class DuplicatePolicy { Skip, Process, Hold };

struct PathsConfig {
  std::filesystem::path watch_dir;     // where scans are dropped (the hot folder)
  std::filesystem::path spool_dir;     // work/, done/, failed/, held/ live here
  std::filesystem::path machines_dir;  // machine profiles (*.toml) for the toolpath module
  std::filesystem::path hides_dir;       // hide files dropped here lie on a cutter's table ("" = no hides)
  std::filesystem::path hide_stock_dir;  // digitized hides kept in stock, for `lastcut hide load` ("" = none)
  std::filesystem::path styles_dir;      // style folders a job's sidecar names with style = "NAME" ("" = none)
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
  // The pen also draws the pieces' sew lines (DXF-AAMA layer 14; a style piece's seams), besides their
  // internal lines (layer 8): the closing room stitches along them. False: internal lines only.
  bool draw_sew_lines = true;
  int compute_workers = 1;          // scans computed at the same time
  double stop_grace_s = 60;         // on SIGTERM, a cut in progress may finish this long, then it is held
};

struct BatchConfig {
  double window_s = 0;  // collect molds per material and cutter this long before nesting (0: nest each job alone)
  int max_pieces = 0;   // ... or until this many pieces wait (0: no piece limit)
  double nest_time_s = 10;  // time the nester may spend improving one batch's layout
};

// strip: a roll or rectangular blank (width_mm x length_mm), nested in batches;
// hide: leather hides, each nested when its file arrives in paths.hides (docs/hides.md).
enum class MaterialKind { Strip, Hide };

// The material the molds are nested on.
struct MaterialConfig {
  MaterialKind kind = MaterialKind::Strip;
  double width_mm = 0;   // strip only
  double length_mm = 0;  // strip only
  double spacing_mm = 2;
  int rotation_step_deg = 90;  // allowed rotations: multiples of this (360: none)
  // Where a hide of this material goes when its sidecar names no cutter, and where the part of a job of
  // several materials that is of this material is cut ("" = jobs.default_cutter).
  std::string cutter;
  // Hides only.
  bool pairs_same_hide = true;  // pairs = "same_hide": an order's jobs on one hide; "any": each job alone
  bool pieces_side_by_side = false;  // a pair's (or job's) pieces next to each other on their hide, not anywhere on it
  // A shoe's piece and the other foot's copy moved to mirror places about the backbone where the hide
  // has room (engine/nest/hide_mirror_pairs.hpp); false keeps the nester's places (a more compact offcut).
  bool mirror_pairs = true;
  int min_quality = 0;          // lowest leather grade a piece may lie on (zones below are avoided)
  int toe_min_quality = 0;      // the toe/vamp region of a mold needs this grade or better (0 = off)
  double toe_fraction = 0.4;    // that region: this share of the toe-heel distance from the toe notch
  double grain_tolerance_deg = 0;  // heel-to-toe axis along a hide's backbone within this (0 = free)
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

// [status]: live status over MQTT (docs/status-mqtt.md). No table: no MQTT at all.
struct StatusConfig {
  bool enabled = false;              // true when the file has a [status] table
  std::string mqtt_url;              // as written: mqtt://HOST[:PORT] or mqtts://HOST[:PORT]
  std::string host;                  // parsed from mqtt_url
  int port = 1883;                   // 1883 (mqtt), 8883 (mqtts) unless the URL names one
  bool tls = false;                  // mqtts://
  std::string ca_file;               // mqtts: CA certificates (PEM); "" = the system's /etc/ssl/certs
  std::string username, password;    // "" = anonymous
  std::string station;               // this node's name in the topics; default: the host name
  std::string topic_prefix = "lastcut";
  int keepalive_s = 15;              // the broker declares us dead (last will) after 1.5x this silence
  int queue_limit = 1000;            // job events kept while the broker is away (oldest dropped first)
};

struct DaemonConfig {
  PathsConfig paths;
  WatchConfig watch;
  JobsConfig jobs;
  BatchConfig batch;
  std::map<std::string, MaterialConfig> materials;
  std::map<std::string, CutterSection> cutters;
  ReviewConfig review;
  MoldQualityLimits quality;  // [quality]: the gate every half's mold passes before it may be nested (docs/quality-gate.md)
  LogConfig log;
  StatusConfig status;
  std::optional<LedgerConfig> ledger;  // [ledger]: several nodes share one PostgreSQL job ledger
  std::optional<WebConfig> web;        // [web]: the operator's page (docs/operator-page.md)
};

std::string to_string(DuplicatePolicy policy);
std::string to_string(WatchMode mode);

}  // namespace lastcut::daemon
