// Start-up recovery of the spool: whatever a crash or power cut left in work/ and batches/ is
// brought to a consistent state before any new file is taken.
//   batch nesting    -> abandoned; its jobs are nested again (computing is at-least-once); a hide
//                       batch whose hide file is in its folder is nested again as it is
//   batch queued     -> back in its cutter's queue (nothing was sent yet)
//   batch sending    -> held with its jobs: the cutter may have cut part of it (at-most-once)
//   batch cut        -> its jobs still in work/ are moved to done/
//   batch.json without a (known) stage -> held with its jobs: nothing is sent on a guess
//   job claimed      -> computed again (attempts counted: a scan that crashes the daemon every
//                       time ends in failed/ after jobs.max_attempts)
//   state.json without a (known) stage -> the job is held with the reason
//   job folder without state or scan -> an unfinished claim: its files go back to the watch folder
//   unfinished durable writes (temporary files) anywhere lastcutd writes -> removed
#include <spdlog/spdlog.h>

#include "daemon/station/engine_steps.hpp"
#include "daemon/spool_store/job_outcomes.hpp"
#include "daemon/spool_store/spool_store.hpp"
#include "engine/core/durable_file.hpp"

namespace lastcut::daemon {

namespace {

// Temporary files of durable writes a crash cut short, at any depth under `folder` (job
// folders, their molds/, batch folders): never read by anyone, removed before anything runs.
void remove_unfinished_writes(const std::filesystem::path& folder, bool recursive) {
  std::vector<std::filesystem::path> unfinished;
  std::error_code error;
  for (std::filesystem::recursive_directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    if (!recursive) it.disable_recursion_pending();
    if (is_unfinished_write(it->path().filename().string())) {
      unfinished.push_back(it->path());
      it.disable_recursion_pending();
    }
  }
  if (error) spdlog::error("recovery: {} cannot be listed: {}", folder.string(), error.message());
  for (const auto& path : unfinished) {
    std::error_code remove_error;
    std::filesystem::remove_all(path, remove_error);
    if (remove_error) spdlog::error("recovery: cannot remove {}: {}", path.string(), remove_error.message());
  }
  if (!unfinished.empty()) {
    spdlog::info("recovery: {} unfinished write(s) removed under {}", unfinished.size(), folder.string());
  }
}

}  // namespace

void SpoolStore::recover() {
  remove_unfinished_writes(spool_->root(), false);  // status.json
  for (JobFolder folder : {JobFolder::Work, JobFolder::Held}) {
    remove_unfinished_writes(spool_->root() / folder_name(folder), true);
  }
  remove_unfinished_writes(spool_->root() / "batches", true);
  for (const std::string& batch_id : spool_->list_batches()) recover_batch(batch_id);
  const auto ids = spool_->list(JobFolder::Work);
  for (const std::string& id : ids) route(id);
  if (!ids.empty()) spdlog::info("recovery: {} job(s) found in work/, resumed", ids.size());
}

void SpoolStore::hold_recovered_batch(BatchState& batch, const std::string& reason) {
  set_batch_stage(*spool_, batch, BatchStage::Held, reason);  // its jobs' lines follow, each held
  hold_batch_jobs(*spool_, batch, reason);
}

void SpoolStore::recover_batch(const std::string& batch_id) {
  auto batch = spool_->read_batch(batch_id);
  if (!batch) {
    // Killed between making the folder and its first batch.json (the temporaries are gone by now):
    // nothing was in it, its jobs are still computed in work/ and are nested again.
    std::error_code error;
    if (std::filesystem::is_empty(spool_->batch_dir(batch_id), error) &&
        std::filesystem::remove(spool_->batch_dir(batch_id), error)) {
      spdlog::info("recovery: batch {} was being created when lastcutd stopped; its empty folder is removed", batch_id);
      return;
    }
    // Its jobs follow their own stage (route): nested again, or held if it was being sent.
    spdlog::warn("recovery: batch {} has no readable batch.json; left as it is", batch_id);
    return;
  }
  if (!batch->stage_problem.empty()) {
    hold_recovered_batch(*batch, "batch " + batch_id + ": " + batch->stage_problem +
                                     "; not sent, an operator must check it");
    return;
  }
  switch (batch->stage) {
    case BatchStage::Nesting:
      if (!batch->hide_file.empty() && std::filesystem::exists(spool_->batch_dir(batch_id) / batch->hide_file)) {
        // The hide is still on the table: nest its jobs again, or wait for jobs as before.
        if (batch->job_ids.empty()) loaded_hides_.push_back({batch_id, Clock::now()});
        else to_nest(batch_id);
        return;
      }
      set_batch_stage(*spool_, *batch, BatchStage::Abandoned, "lastcutd stopped while nesting; the jobs are nested again");
      return;
    case BatchStage::Queued: enqueue_batch(*batch); return;
    case BatchStage::Sending:
      hold_recovered_batch(*batch, "lastcutd stopped (crash or power cut) while batch " + batch_id +
                                       " was being sent to cutter " + batch->cutter + "; pieces may be partly cut");
      return;
    case BatchStage::Cut: complete_batch_jobs(*spool_, *batch); return;
    case BatchStage::Held: hold_batch_jobs(*spool_, *batch, batch->reason); return;
    case BatchStage::Abandoned:
    case BatchStage::Empty: return;
  }
}

void SpoolStore::undo_unfinished_claim(const std::string& job_id) {
  const auto dir = spool_->job_dir(JobFolder::Work, job_id);
  const auto watch_dir = config()->paths.watch_dir;
  std::error_code error;
  for (std::filesystem::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name == "state.json" || is_unfinished_write(name)) continue;
    if (Status moved = move_durably(it->path(), watch_dir / name); !moved) {
      spdlog::error("recovery: unfinished claim {}: {}", job_id, moved.error());
      return;  // keep the folder: nothing may be lost
    }
  }
  std::filesystem::remove_all(dir, error);
  if (error) {
    spdlog::error("recovery: unfinished claim {}: its files are back in the watch folder, but {} stays: {}", job_id,
                  dir.string(), error.message());
    return;
  }
  if (Status synced = fsync_folder(dir.parent_path()); !synced) {
    spdlog::error("recovery: unfinished claim {}: {}", job_id, synced.error());
  }
  spdlog::info("recovery: claim {} was unfinished; its files are back in the watch folder", job_id);
}

void SpoolStore::route(const std::string& job_id) {
  auto state = spool_->read_state(JobFolder::Work, job_id);
  std::error_code error;
  if (!state || !std::filesystem::exists(spool_->job_dir(JobFolder::Work, job_id) / state->scan_name, error)) {
    undo_unfinished_claim(job_id);
    return;
  }
  known_jobs_.insert(job_id);
  if (!state->sha256.empty() && !hash_to_job_.count(state->sha256)) hash_to_job_[state->sha256] = job_id;
  if (!state->stage_problem.empty()) {
    hold_job(*spool_, *state, state->stage_problem + "; an operator must check the job");
    return;
  }
  // An end already written whose move out of work/ a crash cut short: not a change of stage, only
  // the move finished.
  const auto move_to = [&](JobFolder folder) {
    if (Status moved = spool_->move_job(JobFolder::Work, folder, *state); !moved) {
      report_job_problem(*spool_, JobFolder::Work, *state,
                         "recovery: could not be moved to " + folder_name(folder) + "/: " + moved.error());
    }
  };
  switch (state->stage) {
    case JobStage::Claimed: to_compute(job_id); return;
    case JobStage::Computed: add_to_batcher(*state); return;
    case JobStage::Batched:
    case JobStage::Sending: {
      const auto batch = spool_->read_batch(state->batch_id);
      if (batch && batch->stage_problem.empty() && in_progress(batch->stage)) return;
      if (state->stage == JobStage::Sending) {
        // Bytes may have reached the cutter: never cut it again unasked.
        hold_job(*spool_, *state, "was being sent in batch " + state->batch_id +
                                      ", which did not finish; pieces may be partly cut");
        return;
      }
      state->batch_id.clear();
      set_job_stage(*spool_, *state, JobStage::Computed, "its batch did not finish; nested again",
                    "state not written, nested again anyway");
      add_to_batcher(*state);
      return;
    }
    case JobStage::Cut:
    case JobStage::Skipped: move_to(JobFolder::Done); return;
    case JobStage::Failed: move_to(JobFolder::Failed); return;
    case JobStage::Held: move_to(JobFolder::Held); return;
  }
}

void SpoolStore::scan_work_folder() {
  {
    std::lock_guard lock(ended_mutex_);
    ended_.merge(ended_incoming_);
  }
  std::set<std::string> present;
  for (const std::string& id : spool_->list(JobFolder::Work)) {
    present.insert(id);
    if (known_jobs_.count(id) && ended_.count(id)) {
      // Ended, yet in work/: still on its way out, or already handed back by `lastcut requeue`.
      const auto state = spool_->read_state(JobFolder::Work, id);
      if (!state || has_ended(state->stage)) continue;
      ended_.erase(id);
      known_jobs_.erase(id);
    }
    if (!known_jobs_.count(id)) {
      spdlog::info("job {}: back in work/ (requeued by an operator)", id);
      route(id);
    }
  }
  for (auto it = known_jobs_.begin(); it != known_jobs_.end();) {
    if (present.count(*it)) {
      ++it;
      continue;
    }
    ended_.erase(*it);
    it = known_jobs_.erase(it);
  }
}

}  // namespace lastcut::daemon
