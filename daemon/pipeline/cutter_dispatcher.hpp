#pragma once
// CutterDispatcher: one thread and one queue of batches per cutter, so a cutter that is
// switched off, out of material or in alarm delays only its own batches.
//
// Cutting is AT MOST ONCE. Before the first byte goes out the batch and its jobs are marked
// "sending" on disk (fsync'ed); after that the only ways forward are done/ (the machine said it
// finished) or held/ (anything else: fault, crash, stop). A cutter that cannot be reached
// (probe fails, or the driver reports that nothing was sent) keeps the batch queued and is
// retried every retry_interval_s, with one log line per change of its condition.
#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "daemon/config/daemon_config.hpp"
#include "daemon/station/progress_monitor.hpp"
#include "daemon/job/status_observer.hpp"
#include "daemon/pipeline/work_queue.hpp"
#include "daemon/spool/spool.hpp"
#include "drivers/cutter.hpp"

namespace lastcut::daemon {

class CutterDispatcher {
 public:
  // `settings` returns the cutter's current section (it may change on SIGHUP).
  CutterDispatcher(std::string name, Spool& spool, ProgressMonitor& monitor,
                   std::function<CutterSection()> settings);
  ~CutterDispatcher();
  CutterDispatcher(const CutterDispatcher&) = delete;
  CutterDispatcher& operator=(const CutterDispatcher&) = delete;

  void start();
  void enqueue(const std::string& batch_id);
  // Lets a cut in progress finish for up to grace_s, then cancels it (its batch goes to held/);
  // queued batches stay queued in the spool for the next start.
  void stop(double grace_s);

  const std::string& name() const { return name_; }
  // "idle", "cutting B... (40 %)", "waiting: <reason>" for status and logs.
  std::string condition() const;
  std::size_t queued() const { return queue_.size(); }
  // Live status of this cutter (StatusObserver::cutter_changed); set before start().
  void on_status(std::function<void(const CutterStatus&)> listener) { status_listener_ = std::move(listener); }

 private:
  void run();
  // Returns false when the batch must be tried again later (cutter unreachable).
  bool cut_batch(const std::string& batch_id);
  void set_condition(const std::string& condition);
  void wait_before_retry(double seconds);
  // Dispatcher thread only: tells the status listener, if any.
  void report(const std::string& state, const std::string& batch_id, const std::string& reason,
              const drivers::SendProgress& progress = {});

  std::string name_;
  Spool& spool_;
  ProgressMonitor& monitor_;
  std::function<CutterSection()> settings_;
  WorkQueue<std::string> queue_;
  std::thread thread_;
  std::atomic<bool> stopping_{false};
  std::atomic<bool> cancel_{false};
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool sending_ = false;
  std::string condition_ = "idle";
  std::string last_problem_;
  std::function<void(const CutterStatus&)> status_listener_;
  std::string reported_state_ = "idle";  // dispatcher thread only
};

}  // namespace lastcut::daemon
