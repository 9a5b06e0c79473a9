#include "daemon/spool_store/spool_cut_store.hpp"

#include <spdlog/spdlog.h>

#include "daemon/spool/batch_lock.hpp"
#include "daemon/spool_store/job_outcomes.hpp"

namespace lastcut::daemon {

void SpoolCutStore::enqueue(const std::string& batch_id) {
  std::lock_guard lock(mutex_);
  queue_.push_back(batch_id);
}

std::size_t SpoolCutStore::queued() const {
  std::lock_guard lock(mutex_);
  return queue_.size();
}

std::optional<std::string> SpoolCutStore::next_batch() {
  std::lock_guard lock(mutex_);
  if (queue_.empty()) return std::nullopt;
  return queue_.front();
}

Result<std::optional<CutOrder>> SpoolCutStore::claim() {
  while (true) {
    std::string batch_id;
    {
      std::lock_guard lock(mutex_);
      if (queue_.empty()) return std::optional<CutOrder>{};
      batch_id = queue_.front();
      queue_.pop_front();
    }
    const auto batch = spool_.read_batch(batch_id);
    // Finished or taken back meanwhile; a batch.json without a known stage is held by recovery.
    if (!batch || batch->stage != BatchStage::Queued || !batch->stage_problem.empty()) continue;
    return std::optional<CutOrder>{CutOrder{batch_id, spool_.batch_dir(batch_id) / batch->cut_file, batch->cut_file,
                                            batch_id.substr(0, 16), batch->job_ids.size(), batch->piece_count}};
  }
}

Status SpoolCutStore::mark_sending(const CutOrder& order) {
  // Under the batch's lock: an operator's cancel (spool_view.cpp) comes before or after, never between.
  const auto lock = BatchLock::take(spool_.batch_dir(order.batch_id));
  if (!lock) {
    give_back(order);
    return Status::failure(lock.error());
  }
  auto batch = spool_.read_batch(order.batch_id);
  if (!batch) {
    give_back(order);
    return Status::failure("batch.json of " + order.batch_id + " unreadable");
  }
  if (batch->stage != BatchStage::Queued) {
    // Cancelled since the claim: not given back, it is no longer this cutter's to cut.
    return Status::failure("batch " + order.batch_id + " is " + std::string(to_string(batch->stage)) + " now (" +
                           batch->reason + "), not queued");
  }
  if (!set_batch_stage(spool_, *batch, BatchStage::Sending, "sending to cutter " + cutter_, BatchLine::ByCaller)) {
    give_back(order);
    return Status::failure("batch.json of " + order.batch_id + " not written (see the jobs' reports)");
  }
  return Status::success();
}

void SpoolCutStore::give_back(const CutOrder& order) {
  std::lock_guard lock(mutex_);
  queue_.push_front(order.batch_id);
}

CutEnd SpoolCutStore::record_end(const CutOrder& order, CutEnd end, const std::string& reason,
                                 const std::vector<std::string>& cutter_answer) {
  auto batch = spool_.read_batch(order.batch_id);
  if (!batch) {
    spdlog::error("batch {}: batch.json unreadable, its {} could not be written", order.batch_id, to_string(end));
    return end;
  }
  batch->cutter_answer = cutter_answer;
  batch->reason = reason;
  switch (end) {
    case CutEnd::Cut:
      // Cut, even if batch.json cannot say so: the jobs must reach done/, never be cut again.
      set_batch_stage(spool_, *batch, BatchStage::Cut, "the cutter reported the job finished", BatchLine::ByCaller);
      for (const std::string& id : complete_batch_jobs(spool_, *batch)) computed_(id);
      return CutEnd::Cut;
    case CutEnd::NotSent:
      if (set_batch_stage(spool_, *batch, BatchStage::Queued, "cutter refused before cutting: " + reason,
                          BatchLine::ByCaller)) {
        give_back(order);
        return CutEnd::NotSent;
      }
      // Still `sending` on disk, which recovery would hold: hold it now and say why.
      batch->reason = "cutter " + cutter_ + " refused batch " + order.batch_id + " before cutting (" + reason +
                      "), and its return to the queue could not be written";
      break;
    case CutEnd::Held: break;
  }
  set_batch_stage(spool_, *batch, BatchStage::Held, batch->reason, BatchLine::ByCaller);
  hold_batch_jobs(spool_, *batch, batch->reason);
  return CutEnd::Held;
}

}  // namespace lastcut::daemon
