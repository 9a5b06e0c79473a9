#include "daemon/pipeline/job_outcomes.hpp"

#include <fstream>

#include <spdlog/spdlog.h>

#include "daemon/pipeline/engine_steps.hpp"
#include "daemon/spool/durable_file.hpp"

namespace lastcut::daemon {

void fail_job(const Spool& spool, JobState state, const std::string& reason) {
  state.reason = reason;
  state.advance("failed", reason);
  update_job_report(spool, JobFolder::Work, state.id, {{"stage", "failed"}, {"reason", reason}});
  if (std::string error = spool.move_job(JobFolder::Work, JobFolder::Failed, state); !error.empty()) {
    spdlog::error("{}: could not be moved to failed/: {}", state.label(), error);
    return;
  }
  spdlog::error("{}: {} - moved to failed/", state.label(), reason);
}

void hold_job(const Spool& spool, JobState state, const std::string& reason) {
  state.reason = reason;
  state.advance("held", reason);
  update_job_report(spool, JobFolder::Work, state.id, {{"stage", "held"}, {"reason", reason}});
  if (std::string error = spool.move_job(JobFolder::Work, JobFolder::Held, state); !error.empty()) {
    spdlog::error("{}: could not be moved to held/: {}", state.label(), error);
    return;
  }
  spdlog::warn("{}: {} - moved to held/ (after checking, `lastcut requeue {}`)", state.label(), reason, state.id);
}

void update_job_report(const Spool& spool, JobFolder folder, const std::string& job_id, const nlohmann::json& fields) {
  const auto file = spool.job_dir(folder, job_id) / kReportFile;
  nlohmann::json report = nlohmann::json::object();
  if (std::ifstream in(file); in) {
    report = nlohmann::json::parse(in, nullptr, false);
    if (report.is_discarded() || !report.is_object()) report = nlohmann::json::object();
  }
  report.merge_patch(fields);
  if (std::string error = write_file_durably(file, report.dump(2) + "\n"); !error.empty()) {
    spdlog::error("job {}: report not written: {}", job_id, error);
  }
}

void complete_batch_jobs(const Spool& spool, const BatchState& batch) {
  const auto batch_dir = spool.batch_dir(batch.id);
  for (const std::string& id : batch.job_ids) {
    auto state = spool.read_state(JobFolder::Work, id);
    if (!state) continue;  // already finished before a restart, or requeued elsewhere
    if (state->batch_id != batch.id) continue;
    const auto job_dir = spool.job_dir(JobFolder::Work, id);
    for (const std::string& name : {std::string(kLayoutFile), std::string(kPreviewFile), batch.cut_file}) {
      std::error_code exists_error;
      if (name.empty() || !std::filesystem::exists(batch_dir / name, exists_error)) continue;
      if (std::string error = copy_file_durably(batch_dir / name, job_dir / name); !error.empty()) {
        spdlog::warn("{}: {} not copied into the job folder: {}", state->label(), name, error);
      }
    }
    update_job_report(spool, JobFolder::Work, id,
                      {{"stage", "cut"},
                       {"batch", {{"id", batch.id},
                                  {"material", batch.material},
                                  {"cutter", batch.cutter},
                                  {"utilisation", batch.utilisation},
                                  {"pieces", batch.piece_count},
                                  {"cut_file", batch.cut_file},
                                  {"jobs", batch.job_ids}}},
                       {"cutter_answer", batch.cutter_answer},
                       {"history", state->history}});
    state->advance("cut", "cut on " + batch.cutter + " in batch " + batch.id);
    if (std::string error = spool.move_job(JobFolder::Work, JobFolder::Done, *state); !error.empty()) {
      spdlog::error("{}: cut, but could not be moved to done/: {}", state->label(), error);
      continue;
    }
    spdlog::info("{}: cut on {} (batch {}, utilisation {:.1f} %) - moved to done/", state->label(), batch.cutter,
                 batch.id, 100.0 * batch.utilisation);
  }
}

void hold_batch_jobs(const Spool& spool, const BatchState& batch, const std::string& reason) {
  for (const std::string& id : batch.job_ids) {
    auto state = spool.read_state(JobFolder::Work, id);
    if (!state || state->batch_id != batch.id) continue;
    update_job_report(spool, JobFolder::Work, id, {{"cutter_answer", batch.cutter_answer}});
    hold_job(spool, *state, reason);
  }
}

}  // namespace lastcut::daemon
