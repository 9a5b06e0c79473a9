#pragma once
// ComputePool: the station's compute workers, the same on a spool and on a ledger node; the jobs and
// batches come from a ComputeStore (compute_store.hpp).
//
// One turn of a worker: claim the next job or batch from the store, run its engine step (molds:
// make_job_molds; a strip batch: build_batch; a hide: build_hide), each inside the progress
// monitor's bracket so that a step that hangs longer than jobs.compute_timeout_s starves the
// systemd watchdog, and hand the outcome back to the claim. A store that cannot be asked (the
// ledger away) is one log line per change of its trouble, not one per try.
#include <atomic>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "daemon/config/daemon_config.hpp"
#include "daemon/job/status_observer.hpp"
#include "daemon/station/compute_store.hpp"
#include "daemon/station/progress_monitor.hpp"

namespace lastcut::daemon {

// How often a worker asks its store again: after an empty answer (a ledger shared with other nodes
// cannot wake this node's workers) and after an error.
struct ComputePoolTiming {
  double idle_wait_s = 1.0;
  double retry_wait_s = 2.0;
};

class ComputePool {
 public:
  // `settings` returns the running configuration (SIGHUP may replace it); `store` outlives the pool.
  ComputePool(ComputeStore& store, ProgressMonitor& monitor, std::function<std::shared_ptr<const DaemonConfig>()> settings,
              ComputePoolTiming timing = {});
  ~ComputePool();
  ComputePool(const ComputePool&) = delete;
  ComputePool& operator=(const ComputePool&) = delete;

  // Who hears of every nesting done (NestingStatus); call before start. Null: nobody.
  void observe(StatusObserver* observer) { observer_ = observer; }
  // Starts `workers` threads, named compute-1, compute-2, ...
  void start(int workers);
  // New work may be in the store: idle workers ask now rather than after idle_wait_s.
  void wake();
  // Lets each worker finish the step in its hands, then joins them; unclaimed work stays in the store.
  void stop();

  // One turn of a worker, for tests that drive the pool without threads: true when a job or batch
  // was computed, false when the store had none or could not be asked.
  bool turn(const std::string& worker);
  // The store's trouble as last logged ("" when it answered).
  std::string trouble() const;

 private:
  // The engine steps of one claim, inside the watchdog bracket of the progress monitor.
  JobMolds compute_molds(const MoldsWork& work, const std::string& worker);
  NestResult compute_nest(const NestWork& work, const std::string& worker);
  void run(const std::string& worker);
  void note_trouble(const std::string& trouble);
  void wait(double seconds);

  ComputeStore& store_;
  ProgressMonitor& monitor_;
  std::function<std::shared_ptr<const DaemonConfig>()> settings_;
  ComputePoolTiming timing_;
  std::vector<std::thread> threads_;
  std::atomic<bool> stopping_{false};
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  unsigned wakes_ = 0;  // counts wake() calls: a waiter returns when it changed
  std::string trouble_;
  StatusObserver* observer_ = nullptr;
};

}  // namespace lastcut::daemon
