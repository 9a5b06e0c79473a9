#include "daemon/spool_store/job_outcomes.hpp"

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

// Marks the job's end in its report, then moves it there; false when it could not be moved.
bool end_job(const Spool& spool, JobState& state, JobStage stage, const std::string& reason) {
  std::string why = reason;
  if (Status reported = update_job_report(spool, JobFolder::Work, state.id,
                                          {{"stage", to_string(stage)}, {"reason", reason}});
      !reported) {
    spdlog::error("{}: {}", state.label(), reported.error());
    why += " (" + reported.error() + ")";
  }
  return set_job_stage(spool, state, stage, why, "could not be moved out of work/ (" + why + ")");
}

// Where a job of `stage` lives: work/ until it ends.
JobFolder folder_of(JobStage stage) {
  switch (stage) {
    case JobStage::Failed: return JobFolder::Failed;
    case JobStage::Held: return JobFolder::Held;
    case JobStage::Cut:
    case JobStage::Skipped: return JobFolder::Done;
    default: return JobFolder::Work;
  }
}

// A part of a job of several materials was cut in `batch`: noted in the job's report (parts_cut, with
// the batch whose folder keeps its layout and cut file); when another part follows, the job becomes
// computed with it and true is returned. After the last part: false, and the job ends as a whole job does.
bool cut_part(const Spool& spool, JobState& state, const BatchState& batch) {
  nlohmann::json report = read_report(spool.job_dir(JobFolder::Work, state.id) / kReportFile);
  nlohmann::json cut = report.contains("parts_cut") && report["parts_cut"].is_array() ? report["parts_cut"]
                                                                                     : nlohmann::json::array();
  cut.push_back({{"material", batch.material}, {"batch", batch.id}, {"cutter", batch.cutter},
                 {"pieces", state.piece_count}, {"cut_file", batch.cut_file}, {"at", utc_now_iso()}});
  std::string noted;
  if (Status reported = update_job_report(spool, JobFolder::Work, state.id, {{"parts_cut", cut}}); !reported)
    noted = " (" + reported.error() + ")";
  const std::string done = fmt::format("{} cut on {} (batch {})", pieces_of(state.piece_count, batch.material),
                                       batch.cutter, batch.id);
  if (!state.next_part()) return false;
  set_job_stage(spool, state, JobStage::Computed,
                fmt::format("{}; next part {} of {}: {} for {}{}", done, state.part + 1, state.parts.size(),
                            pieces_of(state.piece_count, state.ticket.material), state.ticket.cutter, noted),
                "part cut, but the next part is not written (the next start tries again)");
  return true;
}

}  // namespace

bool set_job_stage(const Spool& spool, JobState& state, JobStage stage, const std::string& note,
                   const std::string& if_not_written) {
  const JobFolder to = folder_of(stage);
  if (to != JobFolder::Work || stage == JobStage::Skipped) state.reason = note;
  state.advance(stage, note);
  if (Status moved = spool.move_job(JobFolder::Work, to, state); !moved) {
    report_job_problem(spool, JobFolder::Work, state, if_not_written + ": " + moved.error());
    return false;
  }
  switch (stage) {
    case JobStage::Failed: spdlog::error("{}: {} - moved to failed/", state.label(), note); break;
    case JobStage::Held:
      spdlog::warn("{}: {} - moved to held/ (after checking, `lastcut requeue {}`)", state.label(), note, state.id);
      break;
    default:
      if (to == JobFolder::Work) spdlog::info("{}: {}", state.label(), note);
      else spdlog::info("{}: {} - moved to {}/", state.label(), note, folder_name(to));
  }
  return true;
}

void fail_job(const Spool& spool, JobState state, const std::string& reason) {
  end_job(spool, state, JobStage::Failed, reason);
}

void hold_job(const Spool& spool, JobState state, const std::string& reason) {
  end_job(spool, state, JobStage::Held, reason);
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

std::string batch_label(const BatchState& batch) {
  if (!batch.hide_id.empty()) return "hide " + batch.hide_id + " (batch " + batch.id + ")";
  if (!batch.hide_file.empty()) return "hide file " + batch.hide_file + " (batch " + batch.id + ")";
  return "batch " + batch.id;
}

bool set_batch_stage(const Spool& spool, BatchState& batch, BatchStage stage, const std::string& note, BatchLine line,
                     const std::string& if_not_written) {
  const bool end = stage == BatchStage::Held || stage == BatchStage::Abandoned || stage == BatchStage::Empty;
  batch.stage = stage;
  if (end) batch.reason = note;
  batch.updated_at = utc_now_iso();
  if (Status written = spool.write_batch(batch); !written) {
    report_batch_problem(spool, batch,
                         (if_not_written.empty() ? std::string(to_string(stage)) + " (" + note +
                                                       "), but batch.json not written"
                                                 : if_not_written) +
                             ": " + written.error());
    return false;
  }
  // Only nesting, queued and sending change the stage of jobs that stay in work/.
  const bool nesting = stage == BatchStage::Nesting;
  if (nesting || stage == BatchStage::Queued || stage == BatchStage::Sending) {
    const JobStage follows = stage == BatchStage::Sending ? JobStage::Sending : JobStage::Batched;
    const std::string joined = (batch.hide_file.empty() ? "nested in " : "nested on ") + batch_label(batch);
    for (const std::string& id : batch.job_ids) {
      auto state = spool.read_state(JobFolder::Work, id);
      if (!state) continue;
      if (nesting) {
        state->batch_id = batch.id;
        state->reason.clear();  // no longer waiting for a hide
        set_job_stage(spool, *state, follows, joined, "not part of " + batch_label(batch) + ": state not written");
      } else if (state->batch_id == batch.id && state->stage != follows) {
        set_job_stage(spool, *state, follows, note);
      }
    }
  }
  if (line == BatchLine::Logged) {
    if (end) spdlog::warn("{}: {}{}", batch_label(batch), note, stage == BatchStage::Empty ? "; nothing is cut" : "");
    else spdlog::info("{}: {}", batch_label(batch), note);
  }
  return true;
}

void report_batch_problem(const Spool& spool, const BatchState& batch, const std::string& problem) {
  spdlog::error("{}: {}", batch_label(batch), problem);
  for (const std::string& id : batch.job_ids) {
    if (!spool.read_state(JobFolder::Work, id)) continue;  // no longer in work/: not this batch's any more
    if (Status noted = append_problem(spool, JobFolder::Work, id, "batch " + batch.id + ": " + problem); !noted) {
      spdlog::error("job {}: {}", id, noted.error());
    }
  }
}

std::vector<std::string> complete_batch_jobs(const Spool& spool, const BatchState& batch) {
  const auto batch_dir = spool.batch_dir(batch.id);
  std::vector<std::string> next_parts;
  for (const std::string& id : batch.job_ids) {
    auto state = spool.read_state(JobFolder::Work, id);
    if (!state) continue;  // already finished before a restart, or requeued elsewhere
    if (state->batch_id != batch.id) continue;
    if (!state->parts.empty() && cut_part(spool, *state, batch)) {
      next_parts.push_back(id);
      continue;
    }
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
    std::string note = fmt::format("cut on {} (batch {}, utilisation {:.1f} %)", batch.cutter, batch.id,
                                   100.0 * batch.utilisation);
    if (Status reported = update_job_report(spool, JobFolder::Work, id, fields); !reported) {
      spdlog::error("{}: {}", state->label(), reported.error());
      note += " (" + reported.error() + ")";
    }
    set_job_stage(spool, *state, JobStage::Cut, note, "cut, but could not be moved to done/");
  }
  return next_parts;
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
