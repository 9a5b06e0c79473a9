#pragma once
// SpoolStore: the store of one station on its spool folder (station/station_store.hpp), what the
// Station (station/station.hpp) runs when the configuration has no [ledger].
//
//   watch folder --take_scan: claim--> work/ID --compute pool (SpoolComputeStore)--> molds (computed)
//     --batcher (tick: per material and cutter, window_s or max_pieces)--> batches/BID (nest, cut file)
//     --the cutter's worker (SpoolCutStore)--> done/ID | held/ID       (bad input anywhere: failed/ID)
//
// The main thread claims files, routes jobs and closes batches (tick); the station's compute pool
// makes molds and batches, each cutter's worker cuts. Only ids travel between threads; the spool on
// disk is the truth, so open() first recovers whatever a crash left behind: computing is
// at-least-once (redone), cutting is at-most-once (an interrupted cut is held).
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "daemon/config/daemon_config.hpp"
#include "daemon/spool_store/spool_compute_store.hpp"
#include "daemon/spool_store/spool_cut_store.hpp"
#include "daemon/spool/spool.hpp"
#include "daemon/station/config_reload.hpp"
#include "daemon/station/station_store.hpp"
#include "daemon/station/strip_batcher.hpp"

namespace lastcut::daemon {

class SpoolStore : public StationStore {
 public:
  explicit SpoolStore(const RunningConfig& config) : config_(config) {}
  ~SpoolStore() override { close(); }
  SpoolStore(const SpoolStore&) = delete;
  SpoolStore& operator=(const SpoolStore&) = delete;

  // Prepares the spool and recovers it (recovery.cpp).
  Status open(const StationLinks& links) override;
  ComputeStore* compute_store() override { return compute_store_.get(); }
  ComputePoolTiming compute_timing() const override { return {}; }  // the spool wakes its workers itself
  std::vector<StationCutter> cutters() override;
  Intake take_scan(const ReadyScan& ready) override;
  Intake take_hide(const ReadyScan& ready) override;
  // Requeued jobs, finished computations, due batches and hides, status.json.
  void tick(Clock::time_point now) override;
  std::string where() const override;
  std::string status_line() const override;
  void stopping() override {}
  // Queued work stays in the spool for the next start.
  void close() override;

 private:
  std::shared_ptr<const DaemonConfig> config() const;
  // recovery.cpp
  void recover();
  void recover_batch(const std::string& batch_id);
  void hold_recovered_batch(BatchState& batch, const std::string& reason);
  void route(const std::string& job_id);
  void undo_unfinished_claim(const std::string& job_id);
  // claims.cpp
  void index_hashes();
  // Hands a claimed job (molds) or a batch in `nesting` to the compute pool.
  void to_compute(const std::string& job_id);
  void to_nest(const std::string& batch_id);
  // batching.cpp
  void add_to_batcher(const JobState& state);
  void close_due_batches(Clock::time_point now);
  void close_batch(const DueBatch& due);
  void enqueue_batch(const BatchState& batch);
  // hide_intake.cpp
  bool is_hide_material(const std::string& material) const;
  void add_to_hide_pool(const JobState& state);
  // Nests each loaded hide that the hide rule finds due (daemon/station/hide_policy.hpp).
  void nest_due_hides(Clock::time_point now);
  bool computing_material(const std::string& material) const;
  void fail_hide(BatchState& batch, const std::string& reason);
  void scan_work_folder();
  // spool/status.json for `lastcut status`: cutters' conditions, queue sizes, pid, time.
  void write_status_file();

  const RunningConfig& config_;
  StationLinks links_;
  std::unique_ptr<Spool> spool_;
  std::unique_ptr<SpoolComputeStore> compute_store_;
  std::map<std::string, std::unique_ptr<SpoolCutStore>> cutters_;  // each cutter's queue of batches

  // Main thread only.
  std::set<std::string> known_jobs_;                  // ids in work/ that have been routed
  std::map<std::string, std::string> hash_to_job_;    // sha256 -> first job id with those bytes
  StripBatcher strip_batcher_;                        // computed jobs waiting for a strip batch
  std::map<std::string, std::vector<std::string>> hide_waiting_;  // hide material -> jobs waiting, oldest first
  std::map<std::string, int> hide_waiting_pieces_;                // job id -> its pieces (for status.json)
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
