#include "daemon/pipeline/job_outcomes.hpp"

#include <fstream>

#include <spdlog/spdlog.h>

#include "daemon/station/engine_steps.hpp"
#include "engine/core/durable_file.hpp"

namespace lastcut::daemon {
namespace {

nlohmann::json read_report(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return nlohmann::json::object();
  nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
  return report.is_discarded() || !report.is_object() ? nlohmann::json::object() : report;
}

Status write_report(const std::filesystem::path& file, const nlohmann::json& report) {
  return write_file_durably(file, report.dump(2) + "\n").with_context("report.json not written: ");
}

Status append_problem(const Spool& spool, JobFolder folder, const std::string& job_id, const std::string& problem) {
  const auto file = spool.job_dir(folder, job_id) / kReportFile;
  nlohmann::json report = read_report(file);
  if (!report["problems"].is_array()) report["problems"] = nlohmann::json::array();
  report["problems"].push_back({{"at", utc_now_iso()}, {"problem", problem}});
  return write_report(file, report);
}

// Moves the job to its end folder with `stage` and `reason`; the report says the same.
// Returns false (after logging) when the job could not be moved.
bool end_job(const Spool& spool, JobState& state, JobStage stage, JobFolder to, const std::string& reason) {
  state.reason = reason;
  if (Status reported = update_job_report(spool, JobFolder::Work, state.id,
                                          {{"stage", to_string(stage)}, {"reason", reason}});
      !reported) {
    spdlog::error("{}: {}", state.label(), reported.error());
    state.reason += " (" + reported.error() + ")";
  }
  state.advance(stage, state.reason);
  if (Status moved = spool.move_job(JobFolder::Work, to, state); !moved) {
    report_job_problem(spool, JobFolder::Work, state,
                       "could not be moved to " + folder_name(to) + "/ (" + state.reason + "): " + moved.error());
    return false;
  }
  return true;
}

}  // namespace

void fail_job(const Spool& spool, JobState state, const std::string& reason) {
  if (end_job(spool, state, JobStage::Failed, JobFolder::Failed, reason)) {
    spdlog::error("{}: {} - moved to failed/", state.label(), state.reason);
  }
}

void hold_job(const Spool& spool, JobState state, const std::string& reason) {
  if (end_job(spool, state, JobStage::Held, JobFolder::Held, reason)) {
    spdlog::warn("{}: {} - moved to held/ (after checking, `lastcut requeue {}`)", state.label(), state.reason,
                 state.id);
  }
}

Status update_job_report(const Spool& spool, JobFolder folder, const std::string& job_id,
                         const nlohmann::json& fields) {
  const auto file = spool.job_dir(folder, job_id) / kReportFile;
  nlohmann::json report = read_report(file);
  report.merge_patch(fields);
  return write_report(file, report);
}

void report_job_problem(const Spool& spool, JobFolder folder, const JobState& state, const std::string& problem) {
  spdlog::error("{}: {}", state.label(), problem);
  if (Status noted = append_problem(spool, folder, state.id, problem); !noted) {
    spdlog::error("{}: {}", state.label(), noted.error());
  }
}

void report_batch_problem(const Spool& spool, const BatchState& batch, const std::string& problem) {
  spdlog::error("batch {}: {}", batch.id, problem);
  for (const std::string& id : batch.job_ids) {
    if (!spool.read_state(JobFolder::Work, id)) continue;  // no longer in work/: not this batch's any more
    if (Status noted = append_problem(spool, JobFolder::Work, id, "batch " + batch.id + ": " + problem); !noted) {
      spdlog::error("job {}: {}", id, noted.error());
    }
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
      if (Status copied = copy_file_durably(batch_dir / name, job_dir / name); !copied) {
        report_job_problem(spool, JobFolder::Work, *state, name + " not copied into the job folder: " + copied.error());
      }
    }
    const nlohmann::json fields{{"stage", to_string(JobStage::Cut)},
                                {"batch", {{"id", batch.id},
                                           {"material", batch.material},
                                           {"cutter", batch.cutter},
                                           {"utilisation", batch.utilisation},
                                           {"pieces", batch.piece_count},
                                           {"cut_file", batch.cut_file},
                                           {"jobs", batch.job_ids}}},
                                {"cutter_answer", batch.cutter_answer},
                                {"history", state->history}};
    std::string note = "cut on " + batch.cutter + " in batch " + batch.id;
    if (Status reported = update_job_report(spool, JobFolder::Work, id, fields); !reported) {
      spdlog::error("{}: {}", state->label(), reported.error());
      note += " (" + reported.error() + ")";
    }
    state->advance(JobStage::Cut, note);
    if (Status moved = spool.move_job(JobFolder::Work, JobFolder::Done, *state); !moved) {
      report_job_problem(spool, JobFolder::Work, *state, "cut, but could not be moved to done/: " + moved.error());
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
    std::string why = reason;
    if (Status reported = update_job_report(spool, JobFolder::Work, id, {{"cutter_answer", batch.cutter_answer}});
        !reported) {
      why += " (" + reported.error() + ")";
    }
    hold_job(spool, *state, why);
  }
}

}  // namespace lastcut::daemon
