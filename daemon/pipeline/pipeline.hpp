#pragma once
// Pipeline: the daemon's job flow, driven by the main loop's tick().
//
//   watch folder --claim--> work/ID --compute worker--> molds (computed)
//     --batcher (per material and cutter: window_s or max_pieces)--> batches/BID (nest, cut file)
//     --one cutter worker per cutter--> done/ID | held/ID       (bad input anywhere: failed/ID)
//
// The main thread claims files, routes jobs and closes batches; compute workers make molds and
// batches; each cutter has its own worker thread (station/cutter_worker.hpp on a SpoolCutStore). Only ids travel between threads; the
// spool on disk is the truth, so start() first recovers whatever a crash left behind:
// computing is at-least-once (redone), cutting is at-most-once (an interrupted cut is held).
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "daemon/config/daemon_config.hpp"
#include "daemon/pipeline/spool_cut_store.hpp"
#include "daemon/station/job_flow.hpp"
#include "daemon/station/progress_monitor.hpp"
#include "daemon/job/status_observer.hpp"
#include "daemon/pipeline/work_queue.hpp"
#include "daemon/spool/spool.hpp"
#include "daemon/station/batching_policy.hpp"
#include "daemon/station/config_reload.hpp"
#include "daemon/station/cutter_worker.hpp"
#include "daemon/watch/hot_folder.hpp"

namespace lastcut::daemon {

class Pipeline : public JobFlow {
 public:
  explicit Pipeline(std::shared_ptr<const DaemonConfig> config);
  ~Pipeline() override;
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  void set_observer(StatusObserver* observer) override { observer_ = observer; }
  // Prepares the spool, recovers it, starts watching and the worker threads.
  Status start() override;
  // New files, requeued jobs, finished computations, due batches.
  void tick(Clock::time_point now) override;
  int event_fd() const override { return hot_folder_ ? hot_folder_->event_fd() : -1; }
  void read_events() override {
    if (hot_folder_) hot_folder_->read_events();
    if (hide_folder_) hide_folder_->read_events();  // its events are read here; tick() runs every 100 ms anyway
  }
  std::string stuck(Clock::time_point now) const override { return monitor_.stuck(now); }
  std::string status_line() const override;
  // Paths, watch mode and the set of cutters need a restart: the returned line says which of
  // those changed and were kept.
  std::string reload(std::shared_ptr<const DaemonConfig> config) override;
  // Queued work stays in the spool for the next start.
  void stop() override;

 private:
  struct Task {
    bool is_batch = false;
    std::string id;
  };
  // A computed job waiting for a strip batch (batching_policy.hpp decides when).
  struct StripWaiting {
    std::string id, material, cutter;
    int pieces = 1;
    Clock::time_point since;
  };

  std::shared_ptr<const DaemonConfig> config() const;
  // recovery.cpp
  void recover();
  void recover_batch(const std::string& batch_id);
  void hold_recovered_batch(BatchState& batch, const std::string& reason);
  void route(const std::string& job_id);
  void undo_unfinished_claim(const std::string& job_id);
  // claims.cpp
  void take(const ReadyScan& ready);
  void index_hashes();
  // workers.cpp
  void compute_worker(int index);
  void compute_job(const std::string& job_id, const std::string& worker);
  void build_batch_task(const std::string& batch_id, const std::string& worker);
  // batching.cpp
  void add_to_batcher(const JobState& state);
  void close_due_batches(Clock::time_point now, bool force);
  void close_batch(const DueBatch& due);
  void enqueue_batch(const BatchState& batch);
  // hide_intake.cpp
  bool is_hide_material(const std::string& material) const;
  void add_to_hide_pool(const JobState& state);
  void take_hide(const ReadyScan& ready);
  // Nests each loaded hide that the hide rule finds due (daemon/station/hide_policy.hpp).
  void nest_due_hides(Clock::time_point now);
  bool computing_material(const std::string& material) const;
  void fail_hide(BatchState& batch, const std::string& reason);
  void build_hide_task(BatchState& batch, const std::string& worker);
  void scan_work_folder();
  // spool/status.json for `lastcut status`: cutters' conditions, queue sizes, pid, time.
  void write_status_file();

  RunningConfig config_;
  std::unique_ptr<Spool> spool_;
  StatusObserver* observer_ = nullptr;
  std::unique_ptr<HotFolder> hot_folder_;
  std::unique_ptr<HotFolder> hide_folder_;  // paths.hides; null when no hides are configured
  ProgressMonitor monitor_;
  WorkQueue<Task> tasks_;
  std::vector<std::thread> workers_;
  // One per cutter: its queue of batches on the spool and the worker that cuts them.
  struct Cutter {
    std::unique_ptr<SpoolCutStore> store;
    std::unique_ptr<CutterWorker> worker;
  };
  std::map<std::string, Cutter> cutters_;

  // Main thread only.
  std::set<std::string> known_jobs_;                  // ids in work/ that have been routed
  std::map<std::string, std::string> hash_to_job_;    // sha256 -> first job id with those bytes
  std::vector<StripWaiting> strip_waiting_;           // computed, waiting for a strip batch, oldest first
  std::map<std::string, std::vector<std::string>> hide_waiting_;  // hide material -> jobs waiting, oldest first
  struct LoadedHide {
    std::string batch_id;
    Clock::time_point since;
  };
  std::vector<LoadedHide> loaded_hides_;  // hides on a cutter's table, waiting for jobs, oldest first
  Clock::time_point next_work_scan_{};
  Clock::time_point next_status_file_{};
  std::string status_file_error_;  // last failure writing status.json, "" when it worked

  // Filled by workers, drained by the main thread.
  std::mutex computed_mutex_;
  std::vector<std::string> computed_;
  // Jobs whose state was written as ended (any thread), drained into ended_ (main thread): a known
  // job found in work/ again with a live stage was requeued by an operator, however soon after it left.
  std::mutex ended_mutex_;
  std::set<std::string> ended_incoming_;
  std::set<std::string> ended_;
};

}  // namespace lastcut::daemon
