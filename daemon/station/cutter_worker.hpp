#pragma once
// CutterWorker: one cutter's thread, the same on a spool and on a ledger node; its batches come
// from a CutStore (cut_store.hpp). A cutter that is switched off, out of material or in alarm
// delays only its own batches.
//
// One turn: when the store may have work, probe the cutter; when it answers, claim its oldest
// batch, mark it `sending` (the point of no return), send exactly the stored cut file, and record
// the end the driver's outcome maps to (cut_end_of): cut, queued again (nothing reached the
// machine; retried every retry_interval_s), or held (maybe partly cut; never sent again by itself).
// Each change of the cutter's condition is one log line and one status report, not one per try.
#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "daemon/config/daemon_config.hpp"
#include "daemon/job/status_observer.hpp"
#include "daemon/station/cut_store.hpp"
#include "daemon/station/cutter_pauses.hpp"
#include "daemon/station/progress_monitor.hpp"

namespace lastcut::daemon {

class CutterWorker;
// Stops the workers in parallel: each gets the whole grace time for the cut in its hands.
void stop_cutter_workers(const std::vector<CutterWorker*>& workers, double grace_s);

class CutterWorker {
 public:
  // `settings` returns the cutter's current section (SIGHUP may change it); `store` outlives the worker.
  CutterWorker(std::string cutter, CutStore& store, ProgressMonitor& monitor, std::function<CutterSection()> settings);
  ~CutterWorker();
  CutterWorker(const CutterWorker&) = delete;
  CutterWorker& operator=(const CutterWorker&) = delete;

  // Live status of this cutter (StatusObserver::cutter_changed); set before start().
  void on_status(std::function<void(const CutterStatus&)> listener) { status_listener_ = std::move(listener); }
  // The operator's pauses (cutter_pauses.hpp), asked at every turn; set before start(), outlives the worker.
  void set_pauses(const CutterPauses* pauses) { pauses_ = pauses; }
  // Starts the thread; `first` is the cutter's state until its next batch (a batch held by an earlier run).
  void start(const CutterStatus& first);
  // New work may be in the store: the next turn comes now rather than after the idle wait.
  void wake();
  // Lets a cut in progress finish for up to grace_s, then cancels it (its batch is held); queued
  // batches stay queued in the store.
  void stop(double grace_s);

  const std::string& name() const { return cutter_; }
  // "idle", "cutting B... (40 %)", "waiting: <reason>" for status lines.
  std::string condition() const;
  bool cutting() const;

  // One turn of the thread, for tests that drive the worker without its thread: how long to wait
  // before the next turn, in seconds (0: at once).
  double turn();

 private:
  void run();
  // Sends one claimed batch; false when it must be tried again later (nothing reached the machine).
  bool cut(const CutOrder& order, const CutterSection& section);
  void set_condition(const std::string& condition);
  // Logs a change of the cutter's or the store's trouble once ("" = no trouble now).
  // `next_batch` is named in the status report ("" when the store cannot name it).
  void note_cutter_problem(const std::string& problem, const std::string& state, const std::string& next_batch,
                           double retry_s);
  void note_store_trouble(const std::string& trouble);
  // True while an operator has this cutter paused; reports the change once.
  bool paused();
  void report(const std::string& state, const std::string& batch_id, const std::string& reason,
              const drivers::SendProgress& progress = {});

  std::string cutter_;
  CutStore& store_;
  ProgressMonitor& monitor_;
  std::function<CutterSection()> settings_;
  std::function<void(const CutterStatus&)> status_listener_;
  const CutterPauses* pauses_ = nullptr;
  std::thread thread_;
  std::atomic<bool> stopping_{false};
  std::atomic<bool> cancel_{false};
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool woken_ = false;
  bool sending_ = false;
  std::string condition_ = "idle";
  // Worker thread only.
  std::string cutter_problem_;  // why the probe failed, as last logged
  std::string refusal_;         // why the cutter refused the last batch before cutting, as last logged
  std::string store_trouble_;
  std::string reported_state_ = "idle";
};

}  // namespace lastcut::daemon
