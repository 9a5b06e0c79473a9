// Start-up recovery of the spool: whatever a crash or power cut left in work/ and batches/ is
// brought to a consistent state before any new file is taken.
//   batch "nesting"  -> abandoned; its jobs are nested again (computing is at-least-once)
//   batch "queued"   -> back in its cutter's queue (nothing was sent yet)
//   batch "sending"  -> held with its jobs: the cutter may have cut part of it (at-most-once)
//   batch "cut"      -> its jobs still in work/ are moved to done/
//   job "claimed"    -> computed again (attempts counted: a scan that crashes the daemon every
//                       time ends in failed/ after jobs.max_attempts)
//   job folder without state or scan -> an unfinished claim: its files go back to the watch folder
#include <spdlog/spdlog.h>

#include "daemon/pipeline/engine_steps.hpp"
#include "daemon/pipeline/job_outcomes.hpp"
#include "daemon/pipeline/pipeline.hpp"
#include "daemon/spool/durable_file.hpp"

namespace lastcut::daemon {

namespace {

// Temporary files of writes a crash cut short: never read by anyone, removed at start.
void remove_temporaries(const std::filesystem::path& parent) {
  std::error_code error;
  for (std::filesystem::directory_iterator it(parent, error), end; !error && it != end; it.increment(error)) {
    if (!it->is_directory(error)) continue;
    for (std::filesystem::directory_iterator file(it->path(), error), last; !error && file != last; file.increment(error)) {
      if (file->path().filename().string().rfind(kTemporaryPrefix, 0) == 0) {
        std::error_code remove_error;
        std::filesystem::remove_all(file->path(), remove_error);
      }
    }
  }
}

}  // namespace

void Pipeline::recover() {
  remove_temporaries(spool_->root() / "work");
  remove_temporaries(spool_->root() / "batches");
  for (const std::string& batch_id : spool_->list_batches()) recover_batch(batch_id);
  const auto ids = spool_->list(JobFolder::Work);
  for (const std::string& id : ids) route(id);
  if (!ids.empty()) spdlog::info("recovery: {} job(s) found in work/, resumed", ids.size());
}

void Pipeline::recover_batch(const std::string& batch_id) {
  auto batch = spool_->read_batch(batch_id);
  if (!batch) return;
  if (batch->stage == "nesting") {
    batch->stage = "abandoned";
    batch->reason = "lastcutd stopped while nesting; the jobs are nested again";
    spool_->write_batch(*batch);
  } else if (batch->stage == "queued") {
    enqueue_batch(*batch);
  } else if (batch->stage == "sending") {
    batch->stage = "held";
    batch->reason = "lastcutd stopped (crash or power cut) while batch " + batch_id + " was being sent to cutter " +
                    batch->cutter + "; pieces may be partly cut";
    spool_->write_batch(*batch);
    spdlog::warn("recovery: batch {} was being cut on {} when lastcutd stopped: its jobs are held", batch_id,
                 batch->cutter);
    hold_batch_jobs(*spool_, *batch, batch->reason);
  } else if (batch->stage == "cut") {
    complete_batch_jobs(*spool_, *batch);
  } else if (batch->stage == "held") {
    hold_batch_jobs(*spool_, *batch, batch->reason);
  }
}

void Pipeline::undo_unfinished_claim(const std::string& job_id) {
  const auto dir = spool_->job_dir(JobFolder::Work, job_id);
  const auto watch_dir = config()->paths.watch_dir;
  std::error_code error;
  for (std::filesystem::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name == "state.json" || name.rfind(kTemporaryPrefix, 0) == 0) continue;
    if (std::string failure = move_durably(it->path(), watch_dir / name); !failure.empty()) {
      spdlog::error("recovery: unfinished claim {}: {}", job_id, failure);
      return;  // keep the folder: nothing may be lost
    }
  }
  std::filesystem::remove_all(dir, error);
  fsync_folder(dir.parent_path());
  spdlog::info("recovery: claim {} was unfinished; its files are back in the watch folder", job_id);
}

void Pipeline::route(const std::string& job_id) {
  auto state = spool_->read_state(JobFolder::Work, job_id);
  std::error_code error;
  if (!state || !std::filesystem::exists(spool_->job_dir(JobFolder::Work, job_id) / state->scan_name, error)) {
    undo_unfinished_claim(job_id);
    return;
  }
  known_jobs_.insert(job_id);
  if (!state->sha256.empty() && !hash_to_job_.count(state->sha256)) hash_to_job_[state->sha256] = job_id;
  const std::string& stage = state->stage;
  if (stage == "claimed") {
    tasks_.push({false, job_id});
  } else if (stage == "computed") {
    add_to_batcher(*state);
  } else if (stage == "batched" || stage == "sending") {
    auto batch = spool_->read_batch(state->batch_id);
    if (batch && (batch->stage == "queued" || batch->stage == "sending" || batch->stage == "nesting")) {
      return;  // the batch carries it on (or was just recovered)
    }
    state->batch_id.clear();
    state->advance("computed", "its batch did not finish; nested again");
    spool_->write_state(JobFolder::Work, *state);
    add_to_batcher(*state);
  } else if (stage == "cut" || stage == "skipped") {
    spool_->move_job(JobFolder::Work, JobFolder::Done, *state);
  } else if (stage == "failed") {
    spool_->move_job(JobFolder::Work, JobFolder::Failed, *state);
  } else if (stage == "held") {
    spool_->move_job(JobFolder::Work, JobFolder::Held, *state);
  } else {
    fail_job(*spool_, *state, "unknown stage \"" + stage + "\" in state.json");
  }
}

void Pipeline::scan_work_folder() {
  std::set<std::string> present;
  for (const std::string& id : spool_->list(JobFolder::Work)) {
    present.insert(id);
    if (!known_jobs_.count(id)) {
      spdlog::info("job {}: back in work/ (requeued by an operator)", id);
      route(id);
    }
  }
  for (auto it = known_jobs_.begin(); it != known_jobs_.end();) {
    it = present.count(*it) ? std::next(it) : known_jobs_.erase(it);
  }
}

}  // namespace lastcut::daemon
