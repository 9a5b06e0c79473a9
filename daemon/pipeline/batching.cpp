// Batch nesting: molds of computed jobs are collected per material and cutter, and nested
// together once the window (batch.window_s, counted from the first job) has passed or enough
// pieces (batch.max_pieces) wait. Nesting several orders on one sheet saves leather.
#include <spdlog/spdlog.h>

#include "daemon/pipeline/job_outcomes.hpp"
#include "daemon/pipeline/pipeline.hpp"

namespace lastcut::daemon {

void Pipeline::add_to_batcher(const JobState& state) {
  if (is_hide_material(state.ticket.material)) {
    add_to_hide_pool(state);  // nested when a hide of this material arrives (hide_intake.cpp)
    return;
  }
  const std::string key = state.ticket.material + "|" + state.ticket.cutter;
  auto [it, inserted] = open_batches_.try_emplace(key);
  if (inserted || it->second.job_ids.empty()) it->second.opened = Clock::now();
  it->second.job_ids.push_back(state.id);
  it->second.pieces += std::max(1, state.piece_count);
  // Closed at once when full: many jobs may finish within one tick (after a burst of files),
  // and a batch must never grow past max_pieces (it would no longer fit the table).
  const int max_pieces = config()->batch.max_pieces;
  if (max_pieces > 0 && it->second.pieces >= max_pieces) close_batch(it->first, it->second);
}

void Pipeline::close_due_batches(Clock::time_point now, bool force) {
  const auto settings = config();
  for (auto& [key, open] : open_batches_) {
    if (open.job_ids.empty()) continue;
    const bool window_over =
        std::chrono::duration<double>(now - open.opened).count() >= settings->batch.window_s;
    const bool full = settings->batch.max_pieces > 0 && open.pieces >= settings->batch.max_pieces;
    if (force || window_over || full) close_batch(key, open);
  }
}

void Pipeline::close_batch(const std::string& key, OpenBatch& open) {
  BatchState batch;
  batch.id = spool_->new_batch_id();
  const auto bar = key.find('|');
  batch.material = key.substr(0, bar);
  batch.cutter = key.substr(bar + 1);
  batch.stage = BatchStage::Nesting;
  batch.created_at = batch.updated_at = utc_now_iso();
  // Only jobs still waiting in work/ (an operator may have moved one meanwhile).
  for (const std::string& id : open.job_ids) {
    auto state = spool_->read_state(JobFolder::Work, id);
    if (state && state->stage == JobStage::Computed && state->stage_problem.empty()) batch.job_ids.push_back(id);
  }
  open = OpenBatch{};
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
    state->advance(JobStage::Batched, "nested in batch " + batch.id);
    if (Status state_written = spool_->write_state(JobFolder::Work, *state); !state_written) {
      // Still "computed" on disk: nesting drops it from this batch, the next start nests it again.
      report_job_problem(*spool_, JobFolder::Work, *state,
                         "not part of batch " + batch.id + ": state not written: " + state_written.error());
    }
  }
  tasks_.push({true, batch.id});
}

void Pipeline::enqueue_batch(const BatchState& batch) {
  const auto it = dispatchers_.find(batch.cutter);
  if (it == dispatchers_.end()) {
    spdlog::error("batch {}: cutter {} is not configured; the batch stays queued in the spool", batch.id,
                  batch.cutter);
    return;
  }
  it->second->enqueue(batch.id);
}

}  // namespace lastcut::daemon
