#include "daemon/station/job_molds.hpp"

#include <chrono>

#include <spdlog/spdlog.h>

#include "daemon/station/engine_steps.hpp"
#include "daemon/station/job_mold_options.hpp"

namespace lastcut::daemon {

std::string job_work_noun(const std::filesystem::path& input, const JobTicket& ticket) {
  return is_pattern_set(input) || !ticket.style.empty() ? "pieces" : "molds";
}

JobMolds make_job_molds(const std::filesystem::path& scan, const std::filesystem::path& job_dir, const JobTicket& ticket,
                        const DaemonConfig& settings, ProgressMonitor& monitor, const std::string& worker,
                        const std::string& task, const std::string& label) {
  JobMolds molds;
  const auto start = std::chrono::steady_clock::now();
  monitor.begin(worker, task, settings.jobs.compute_timeout_s);
  const Result<MoldsMade> made =
      is_pattern_set(scan)     ? compute_pattern_items(scan, job_dir, ticket, settings)
      : !ticket.style.empty()  ? compute_style_pieces(scan, job_dir, ticket, settings)
                               : compute_molds(scan, job_dir, ticket, job_mold_options(ticket, settings.jobs),
                                               settings.jobs.max_hole_across_mm, settings.quality);
  molds.took_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!made) {
    monitor.end(worker);
    molds.reason = made.error();
    return molds;
  }
  molds.noun = made->noun;
  if (!made->hold_reason.empty()) {
    monitor.end(worker);
    molds.verdict = JobMolds::Verdict::HeldNotNestable;
    molds.reason = made->hold_reason;
    molds.report = {{"molds", made->piece_count},
                    {"pieces", 0},
                    {"measures", made->measures},
                    {"timings_s", {{"molds", molds.took_s}}}};
    return molds;
  }
  const Result<ReferenceCheck> checked = check_against_references(job_dir, ticket, settings.review.corner_tolerance_mm);
  monitor.end(worker);
  if (!checked) {
    molds.reason = checked.error();
    return molds;
  }
  molds.molds = made->piece_count;
  molds.pieces = made->pieces_to_cut;
  molds.report = {{"molds", molds.molds},
                  {"pieces", molds.pieces},
                  {"measures", made->measures},
                  {"timings_s", {{"molds", molds.took_s}}}};
  if (!checked->comparisons.empty()) molds.report["compare"] = checked->comparisons;
  molds.parts = made->parts;
  if (!molds.parts.empty()) molds.report["parts"] = parts_to_json(molds.parts);
  // What the engine noticed but got past (a side contradicting the sidecar, a scan hole closed)
  // must reach the operator's log, not only report.json.
  if (const auto warnings = made->measures.find("warnings"); warnings != made->measures.end()) {
    for (const auto& warning : *warnings) spdlog::warn("{}: {}", label, warning.get<std::string>());
  }
  molds.verdict = checked->hold_reason.empty() ? JobMolds::Verdict::Computed : JobMolds::Verdict::HeldForReview;
  molds.reason = checked->hold_reason;
  return molds;
}

}  // namespace lastcut::daemon
