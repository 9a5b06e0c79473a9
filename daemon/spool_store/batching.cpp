// Batch nesting on a spool: computed jobs of strip materials wait in the station's StripBatcher
// (daemon/station/strip_batcher.hpp), whose batching rule (the same on a ledger) says when a group
// of them is nested together. Nesting several orders on one sheet saves leather.
#include <spdlog/spdlog.h>

#include "daemon/spool_store/job_outcomes.hpp"
#include "daemon/spool_store/spool_store.hpp"

namespace lastcut::daemon {

void SpoolStore::add_to_batcher(const JobState& state) {
  if (is_hide_material(state.ticket.material)) {
    add_to_hide_pool(state);  // nested when a hide of this material arrives (hide_intake.cpp)
    return;
  }
  strip_batcher_.add({state.id, state.ticket.material, state.ticket.cutter, state.piece_count, 0}, Clock::now());
  // Closed at once when full: many jobs may finish within one tick (after a burst of files),
  // and a batch must never grow past max_pieces (it would no longer fit the table).
  close_due_batches(Clock::now());
}

void SpoolStore::close_due_batches(Clock::time_point now) {
  for (const DueBatch& due : strip_batcher_.take_due(now, config()->batch)) close_batch(due);
}

void SpoolStore::close_batch(const DueBatch& due) {
  BatchState batch;
  batch.id = spool_->new_batch_id();
  batch.material = due.material;
  batch.cutter = due.cutter;
  batch.created_at = utc_now_iso();
  // Only jobs still waiting in work/ (an operator may have moved one meanwhile).
  for (const std::string& id : due.job_ids) {
    auto state = spool_->read_state(JobFolder::Work, id);
    if (state && state->stage == JobStage::Computed && state->stage_problem.empty()) batch.job_ids.push_back(id);
  }
  if (batch.job_ids.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(spool_->batch_dir(batch.id), error);
  if (error) {
    report_batch_problem(*spool_, batch, "cannot create " + spool_->batch_dir(batch.id).string() + ": " +
                                             error.message() + "; its jobs wait for the next start");
    return;
  }
  // A job whose state is not written stays "computed" on disk: nesting drops it from this batch,
  // the next start nests it again.
  if (!set_batch_stage(*spool_, batch, BatchStage::Nesting,
                       fmt::format("nesting {} job(s) of {} for cutter {}", batch.job_ids.size(), batch.material,
                                   batch.cutter),
                       BatchLine::Logged, "cannot be written; its jobs wait for the next start"))
    return;
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
