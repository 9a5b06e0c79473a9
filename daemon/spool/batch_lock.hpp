#pragma once
// BatchLock: one writer at a time for a queued spool batch, across threads and processes. The
// cutter worker's `sending` (the point of no return, spool_cut_store.cpp) and an operator's cancel
// (the page or `lastcut`, spool_view.cpp) each read batch.json, check its stage and write the next
// one; under this lock (flock on batches/BID/.lock) exactly one of them wins, so a cancelled batch
// is never cut and a batch being cut is never cancelled.
#include <filesystem>

#include "engine/core/status.hpp"

namespace lastcut::daemon {

class BatchLock {
 public:
  // Waits for the lock of the batch in `batch_dir`; why not when its lock file cannot be opened.
  static Result<BatchLock> take(const std::filesystem::path& batch_dir);
  ~BatchLock();
  BatchLock(BatchLock&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
  BatchLock& operator=(BatchLock&&) = delete;
  BatchLock(const BatchLock&) = delete;
  BatchLock& operator=(const BatchLock&) = delete;

 private:
  explicit BatchLock(int fd) : fd_(fd) {}
  int fd_ = -1;
};

}  // namespace lastcut::daemon
