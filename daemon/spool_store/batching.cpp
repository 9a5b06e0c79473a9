// Batch nesting on a spool: computed jobs of strip materials wait in strip_waiting_, and the
// station's batching rule (daemon/station/batching_policy.hpp, the same on a ledger) says when a
// group of them is nested together. Nesting several orders on one sheet saves leather.
#include <algorithm>

#include <spdlog/spdlog.h>

#include "daemon/spool_store/job_outcomes.hpp"
#include "daemon/spool_store/spool_store.hpp"

namespace lastcut::daemon {

void SpoolStore::add_to_batcher(const JobState& state) {
  if (is_hide_material(state.ticket.material)) {
    add_to_hide_pool(state);  // nested when a hide of this material arrives (hide_intake.cpp)
    return;
  }
  strip_waiting_.push_back({state.id, state.ticket.material, state.ticket.cutter, state.piece_count, Clock::now()});
  // Closed at once when full: many jobs may finish within one tick (after a burst of files),
  // and a batch must never grow past max_pieces (it would no longer fit the table).
  close_due_batches(Clock::now(), false);
}

void SpoolStore::close_due_batches(Clock::time_point now, bool force) {
  std::vector<WaitingJob> waiting;
  for (const StripWaiting& job : strip_waiting_)
    waiting.push_back({job.id, job.material, job.cutter, job.pieces,
                       std::chrono::duration<double>(now - job.since).count()});
  for (const DueBatch& due : due_batches(waiting, config()->batch, force)) {
    std::erase_if(strip_waiting_, [&](const StripWaiting& job) {
      return std::find(due.job_ids.begin(), due.job_ids.end(), job.id) != due.job_ids.end();
    });
    close_batch(due);
  }
}

void SpoolStore::close_batch(const DueBatch& due) {
  BatchState batch;
  batch.id = spool_->new_batch_id();
  batch.material = due.material;
  batch.cutter = due.cutter;
  batch.stage = BatchStage::Nesting;
  batch.created_at = batch.updated_at = utc_now_iso();
  // Only jobs still waiting in work/ (an operator may have moved one meanwhile).
  for (const std::string& id : due.job_ids) {
    auto state = spool_->read_state(JobFolder::Work, id);
    if (state && state->stage == JobStage::Computed && state->stage_problem.empty()) batch.job_ids.push_back(id);
  }
  if (batch.job_ids.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(spool_->batch_dir(batch.id), error);
  Status written = error ? Status::failure("cannot create " + spool_->batch_dir(batch.id).string() + ": " +
                                          error.message())
                         : spool_->write_batch(batch);
  if (!written) {
    report_batch_problem(*spool_, batch,
                         "cannot be written (" + written.error() + "); its jobs wait for the next start");
    return;
  }
  for (const std::string& id : batch.job_ids) {
    auto state = spool_->read_state(JobFolder::Work, id);
    if (!state) continue;
    state->batch_id = batch.id;
    // Not written: still "computed" on disk, nesting drops it from this batch, the next start nests it again.
    set_job_stage(*spool_, *state, JobStage::Batched, "nested in batch " + batch.id,
                  "not part of batch " + batch.id + ": state not written");
  }
  to_nest(batch.id);
}

void SpoolStore::enqueue_batch(const BatchState& batch) {
  const auto it = cutters_.find(batch.cutter);
  if (it == cutters_.end()) {
    spdlog::error("batch {}: cutter {} is not configured; the batch stays queued in the spool", batch.id,
                  batch.cutter);
    return;
  }
  it->second->enqueue(batch.id);
  links_.wake_cutter(batch.cutter);
}

}  // namespace lastcut::daemon
