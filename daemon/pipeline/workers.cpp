// The compute workers: molds for a claimed job, nesting and cut file for a closed batch.
// Each task is bracketed by the progress monitor, so a computation that hangs longer than
// jobs.compute_timeout_s starves the systemd watchdog.
#include <chrono>

#include <spdlog/spdlog.h>

#include "daemon/station/engine_steps.hpp"
#include "daemon/station/job_molds.hpp"
#include "daemon/pipeline/job_outcomes.hpp"
#include "daemon/pipeline/pipeline.hpp"

namespace lastcut::daemon {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void Pipeline::compute_worker(int index) {
  const std::string worker = "compute-" + std::to_string(index);
  while (auto task = tasks_.pop()) {
    if (task->is_batch) build_batch_task(task->id, worker);
    else compute_job(task->id, worker);
  }
}

void Pipeline::compute_job(const std::string& job_id, const std::string& worker) {
  const auto settings = config();
  auto state = spool_->read_state(JobFolder::Work, job_id);
  if (!state || state->stage != JobStage::Claimed || !state->stage_problem.empty()) return;
  if (state->attempts >= settings->jobs.max_attempts) {
    fail_job(*spool_, *state,
             "computing the molds stopped lastcutd " + std::to_string(state->attempts) +
                 " times (crash or hang); the scan is kept for a developer to look at");
    return;
  }
  // Counted before the work: if this scan crashes the daemon, the next start knows.
  ++state->attempts;
  // Without the count on disk a scan that crashes lastcutd would be computed forever.
  if (!set_job_stage(*spool_, *state, JobStage::Claimed, "computing molds, attempt " + std::to_string(state->attempts),
                     "not computed, its attempt cannot be counted")) {
    return;
  }
  const auto job_dir = spool_->job_dir(JobFolder::Work, job_id);
  const JobMolds molds = make_job_molds(job_dir / state->scan_name, job_dir, state->ticket, *settings, monitor_, worker,
                                        "molds of job " + job_id, state->label());
  if (molds.verdict == JobMolds::Verdict::Failed) {
    fail_job(*spool_, *state, molds.reason);
    return;
  }
  state->piece_count = molds.pieces;
  nlohmann::json report = molds.report;
  report.update({{"job", job_id}, {"scan", state->scan_name}, {"sha256", state->sha256},
                 {"ticket", ticket_to_json(state->ticket)}});
  if (Status reported = update_job_report(*spool_, JobFolder::Work, job_id, report); !reported) {
    fail_job(*spool_, *state, "molds made but " + reported.error());
    return;
  }
  if (!set_job_stage(*spool_, *state, JobStage::Computed,
                     fmt::format("{} molds ready in {:.1f} s", molds.molds, molds.took_s),
                     "molds made, but the state is not written (computed again at the next start)")) {
    return;
  }
  if (molds.verdict == JobMolds::Verdict::HeldForReview) {
    // Computed first: `lastcut requeue` of the held job then nests it as it is (the operator's approval).
    hold_job(*spool_, *state, molds.reason);
    return;
  }
  std::lock_guard lock(computed_mutex_);
  computed_.push_back(job_id);
}

void Pipeline::build_batch_task(const std::string& batch_id, const std::string& worker) {
  const auto settings = config();
  auto batch = spool_->read_batch(batch_id);
  if (!batch || batch->stage != BatchStage::Nesting || !batch->stage_problem.empty()) return;
  if (!batch->hide_file.empty()) {
    build_hide_task(*batch, worker);
    return;
  }
  std::vector<BatchJobInput> inputs;
  std::map<std::string, JobState> states;
  for (const std::string& id : batch->job_ids) {
    auto state = spool_->read_state(JobFolder::Work, id);
    if (!state || state->batch_id != batch_id) continue;
    inputs.push_back({id, spool_->job_dir(JobFolder::Work, id)});
    states.emplace(id, *state);
  }
  const auto material = settings->materials.find(batch->material);
  const auto cutter = settings->cutters.find(batch->cutter);
  const auto start = std::chrono::steady_clock::now();
  const auto nest_batch = [&]() -> Result<BatchMade> {
    if (material == settings->materials.end())
      return Status::failure("material " + batch->material + " is no longer configured");
    if (cutter == settings->cutters.end()) return Status::failure("cutter " + batch->cutter + " is no longer configured");
    monitor_.begin(worker, "nesting batch " + batch_id, settings->jobs.compute_timeout_s);
    Result<BatchMade> made = build_batch(inputs, material->second, cutter->second, settings->paths.machines_dir,
                                         settings->batch.nest_time_s, spool_->batch_dir(batch_id));
    monitor_.end(worker);
    return made;
  };
  const Result<BatchMade> outcome = nest_batch();
  const double took_s = seconds_since(start);
  std::vector<std::string> kept;
  for (auto& [id, state] : states) {
    if (!outcome) {
      hold_job(*spool_, state, "batch " + batch_id + " could not be made: " + outcome.error());
    } else if (auto rejected = outcome->rejected.find(id); rejected != outcome->rejected.end()) {
      fail_job(*spool_, state, rejected->second);
    } else {
      kept.push_back(id);
      if (Status reported =
              update_job_report(*spool_, JobFolder::Work, id, {{"timings_s", {{"nesting_and_cut_file", took_s}}}});
          !reported) {
        report_job_problem(*spool_, JobFolder::Work, state, reported.error());
      }
    }
  }
  batch->job_ids = kept;
  batch->updated_at = utc_now_iso();
  if (!outcome || kept.empty()) {
    batch->stage = BatchStage::Empty;
    batch->reason = outcome ? "no job left in the batch" : outcome.error();
    if (Status written = spool_->write_batch(*batch); !written) {
      // Its jobs have left work/ already; recovery abandons the batch at the next start.
      spdlog::error("batch {}: {}, but batch.json not written: {}", batch_id, batch->reason, written.error());
    }
    return;
  }
  batch->stage = BatchStage::Queued;
  batch->cut_file = outcome->cut_file;
  batch->utilisation = outcome->utilisation;
  batch->piece_count = outcome->piece_count;
  if (Status written = spool_->write_batch(*batch); !written) {
    // Still "nesting" on disk: the next start abandons it and nests its jobs again.
    report_batch_problem(*spool_, *batch, "nested, but not queued: batch.json not written: " + written.error());
    return;
  }
  spdlog::info("batch {}: {} job(s), {} pieces nested on {} (utilisation {:.1f} %) in {:.1f} s; queued for {}",
               batch_id, kept.size(), batch->piece_count, batch->material, 100.0 * batch->utilisation, took_s,
               batch->cutter);
  enqueue_batch(*batch);
}

}  // namespace lastcut::daemon
