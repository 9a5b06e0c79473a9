#pragma once
// StoreView: what `lastcut status`, `lastcut requeue` and lastcutd's operator page (daemon/web) need from the store that keeps the jobs,
// the spool folder of one station (spool_view.cpp) or the shop's PostgreSQL ledger
// (ledger_view.cpp). The two commands (status_command.cpp) are written once against it: one
// overview printed one way, one requeue. Both read the store directly, so they work whether
// lastcutd runs or not; the ledger's view shows the whole shop from any node.
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "daemon/config/daemon_config.hpp"
#include "engine/core/status.hpp"

namespace lastcut::daemon {

// One line of a table, printf-style (both views print fixed-width columns).
inline std::string format_line(const char* pattern, auto... values) {
  char text[512];
  std::snprintf(text, sizeof(text), pattern, values...);
  return text;
}

// One job as an operator finds it.
struct JobLine {
  std::string id;
  std::string state;   // the store's word: claimed, computed, batched, sending, cut, held, failed, skipped / ready, ...
  std::string where;   // spool: its folder (work, done, held, failed); ledger: "on <node>" while a node holds it
  std::string order;   // the ticket's order, "" when none
  std::string scan;    // the scan's file name
  std::string reason;  // why held, failed, waiting; "" otherwise
  std::string parts;   // a job of several materials: which pieces wait for which material (parts_progress)
};

// A nested batch waiting for its cutter: the one kind an operator may cancel.
struct QueuedBatch {
  std::string id;
  std::string cutter;
  long long jobs = 0;
  int pieces = 0;
};

// A hide on a table: loaded, being nested, used (nested and cut or queued), empty.
struct HideLine {
  std::string hide;      // the hide's ID (its name)
  std::string batch_id;  // the batch nested on it, "" before
  std::string cutter;
  std::string material;
  std::string state;     // the store's word (spool: the batch's stage; ledger: the hide's state)
  int pieces = 0;
  double utilisation = 0;  // pieces / usable area, 0..1, once nested
};

// A batch cut in the last 24 hours, for the day's plots.
struct CutBatch {
  std::string batch_id;
  std::string cut_at_utc;  // ISO 8601, "2026-11-28T13:49:37.123Z"
  std::string material;
  long long jobs = 0;
  int pieces = 0;
  double utilisation = 0;  // pieces / material used, 0..1
};

// One job's record, as the operator page's job view shows it.
struct JobRecord {
  std::filesystem::path folder;  // its files (molds/, report.json, ...); may be missing before it is computed
  nlohmann::json state;          // {stage, reason, history: [{at, stage, note}]}: the spool's state.json or the ledger's
};

struct StoreOverview {
  std::string headline;                    // "spool /var/spool/lastcut: 2 in work, ..." or "ledger URL: 3 done, ..."
  std::vector<std::string> station_lines;  // the daemon or the nodes: running, pid, heartbeat
  std::vector<std::string> cutter_lines;   // each cutter's condition and queued batches
  std::map<std::string, long long> waiting_for_hide;  // hide material -> computed jobs waiting for a hide
  std::map<std::string, long long> pieces_waiting_for_hide;  // hide material -> those jobs' pieces
  std::vector<std::string> batch_lines;    // batches in progress or held (spool), hides (ledger)
  std::vector<JobLine> in_work, held, recent;
  std::vector<QueuedBatch> queued_batches;  // oldest first
  std::vector<HideLine> hides;              // newest first, at most 20
  std::vector<CutBatch> cut_last_24h;       // oldest first
  nlohmann::json json;                     // `--json`: the store's own document (docs/daemon.md, multi-station.md)
};

class StoreView {
 public:
  virtual ~StoreView() = default;
  // The store's overview with the `recent_count` newest finished jobs; an error line when the store
  // cannot be read (the ledger away).
  virtual Result<StoreOverview> overview(std::size_t recent_count) = 0;
  // "" when `job_id` has the form of this store's ids, else why not (the caller exits 2).
  virtual std::string id_problem(const std::string& job_id) const = 0;
  // Puts a held or failed job back in the queue (`again`: also a job already cut, where the store
  // allows it). The line to print, or why not.
  virtual Result<std::string> requeue(const std::string& job_id, bool again) = 0;
  // Cancels a batch that waits for its cutter: the batch and its jobs are held with the reason
  // cancel_reason(), so requeueing the jobs nests them again. Atomic against the cutter's claim (the
  // spool's batch lock, the ledger's row lock): a batch already taken is refused with its state.
  // The line to print, or why not.
  virtual Result<std::string> cancel_batch(const std::string& batch_id, const std::string& who) = 0;
  // One job's record; why not when there is no such job.
  virtual Result<JobRecord> job_record(const std::string& job_id) = 0;
};

// The reason a cancelled batch and its jobs are held with, and the line that says it was done.
inline std::string cancel_reason(const std::string& batch_id, const std::string& who) {
  return "batch " + batch_id + " cancelled by " + who + " before it was cut; requeue the job to nest it again";
}
inline std::string cancelled_line(const std::string& batch_id, long long jobs) {
  return "batch " + batch_id + " cancelled: its " + std::to_string(jobs) + " job(s) are held";
}

// The view of the store the configuration names: the ledger when it has [ledger], else its spool
// folder; `spool_dir` (--spool) names a spool folder directly. An error line when the
// configuration cannot be read.
Result<std::unique_ptr<StoreView>> open_store_view(const std::string& config_file, const std::string& spool_dir);
std::unique_ptr<StoreView> open_store_view(const DaemonConfig& config);

// A JSON file of the spool (state.json, report.json, status.json) as read by a viewer: null when
// it is missing or unreadable (a running daemon may be replacing it).
nlohmann::json read_json_or_null(const std::filesystem::path& file);

// The two views (spool_view.cpp, ledger_view.cpp). `hide_materials`: the configuration's materials
// of kind hide, whose computed jobs wait for a hide.
std::unique_ptr<StoreView> make_spool_view(const std::string& spool_dir);
std::unique_ptr<StoreView> make_ledger_view(const LedgerConfig& ledger, std::vector<std::string> hide_materials);

}  // namespace lastcut::daemon
