#pragma once
// The molds step of a job as every station runs it, whichever store keeps the job: the engine's
// molds (compute_molds) and the comparison with the reference patterns the ticket names
// (check_against_references), both inside the progress monitor's bracket, since a comparison that
// hangs must starve the systemd watchdog like a hung flattening; the job report's fields; the
// engine's warnings in the operator's log. What the store does with the verdict (a spool's
// set_job_stage, the ledger's mark_computed / mark_held / mark_failed) stays with the store.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "daemon/config/daemon_config.hpp"
#include "daemon/job/job_parts.hpp"
#include "daemon/job/job_ticket.hpp"
#include "daemon/station/progress_monitor.hpp"

namespace lastcut::daemon {

struct JobMolds {
  enum class Verdict {
    Failed,         // bad input or a step that could not be done: `reason` says why
    HeldNotNestable,  // molds beyond the quality gate, or a style that does not apply to the last: never
                      // nested; a requeue computes them again
    HeldForReview,  // molds made, but a corner lies beyond the tolerance from its reference pattern
    Computed,       // molds made and, where references were named, within tolerance
  };
  Verdict verdict = Verdict::Failed;
  std::string reason;     // Failed: why; HeldNotNestable: the limits crossed; HeldForReview: the worst corner
  int molds = 0;          // molds (or a style's or pattern set's pieces) made
  std::string noun = "molds";  // what they are, for the log: "molds" or "pieces"
  int pieces = 0;         // the pieces to cut (every item x its demand): what batching counts
  std::vector<JobPart> parts;  // a job of several materials: its parts in cutting order (job_parts.hpp)
  double took_s = 0;      // the engine's time for the molds
  nlohmann::json report;  // molds, pieces, measures, timings_s and, when references were named, compare
};

// What make_job_molds makes of `input` under `ticket`, for the log before it starts: "pieces" for a
// pattern set or a style, else "molds".
std::string job_work_noun(const std::filesystem::path& input, const JobTicket& ticket);

// Makes the molds of `scan` (or the pieces of the ticket's style on it, or of a pattern set) into job_dir
// (molds/ or pieces/, items.json; the reference copies are expected in
// job_dir), as `worker` busy on `task` in `monitor`; `label` names the job in log lines.
JobMolds make_job_molds(const std::filesystem::path& scan, const std::filesystem::path& job_dir, const JobTicket& ticket,
                        const DaemonConfig& settings, ProgressMonitor& monitor, const std::string& worker,
                        const std::string& task, const std::string& label);

}  // namespace lastcut::daemon
