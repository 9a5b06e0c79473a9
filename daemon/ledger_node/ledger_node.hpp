#pragma once
// LedgerNode: lastcutd as one node of a shop sharing a PostgreSQL job ledger (docs/multi-station.md),
// in place of the single-station Pipeline when the configuration has [ledger].
//
//   watch folder --intake (main thread)--> shared/scans/<sha> + ledger job `ready`
//   hides folder --intake (main thread)--> shared/hides/<sha> + ledger hide `loaded` on its cutter
//   compute role: claim job (lease) -> molds into shared/jobs/<sha> -> `computed`
//                 group computed jobs ([batch] window_s, max_pieces) -> nest -> shared/batches/<id> -> `queued`
//                 a loaded hide + the computed jobs of its material -> nest on it -> shared/batches/<id> -> `queued`
//                 (the jobs that did not fit: `computed` again, waiting for the next hide, with the reason)
//   station role: a CutterWorker per cutter cabled here (the spool's, against LedgerCutStore):
//                 claim its queued batch -> `sending` -> cut | held | queued again
//
// Every claim holds a lease the LeaseKeeper thread renews; a state change is fenced by the lease's
// epoch, so a node that lost a claim (a long pause, a cut network) only drops its work. The main
// thread sweeps expired leases of any node each heartbeat: what a vanished node computed is
// redone elsewhere, what it was sending is held, never re-sent (at most once, as on one station).
// The database away: intake leaves scans in the watch folder, workers retry, a cut in progress
// finishes and its end is written when the ledger is back; each change of condition is one log line.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "daemon/config/daemon_config.hpp"
#include "daemon/ledger/lease_keeper.hpp"
#include "daemon/ledger/ledger_client.hpp"
#include "daemon/ledger_node/ledger_cut_store.hpp"
#include "daemon/ledger_node/shared_store.hpp"
#include "daemon/station/config_reload.hpp"
#include "daemon/station/cutter_worker.hpp"
#include "daemon/station/job_flow.hpp"
#include "daemon/station/progress_monitor.hpp"
#include "daemon/job/status_observer.hpp"
#include "daemon/job/job_ticket.hpp"
#include "daemon/watch/hot_folder.hpp"

namespace lastcut::daemon {

// A ticket as the intake stored it in the ledger (ticket_to_json); a row no lastcutd wrote is refused.
Result<JobTicket> ticket_from_ledger(const std::string& text);

class LedgerNode : public JobFlow {
 public:
  explicit LedgerNode(std::shared_ptr<const DaemonConfig> config);
  ~LedgerNode() override;
  LedgerNode(const LedgerNode&) = delete;
  LedgerNode& operator=(const LedgerNode&) = delete;

  void set_observer(StatusObserver* observer) override { observer_ = observer; }
  // Connects, migrates the schema, registers the node and its cutters (handing back what an earlier
  // run left), starts watching and the worker threads.
  Status start() override;
  // Intake of ready scans; the sweep of expired leases each heartbeat.
  void tick(Clock::time_point now) override;
  int event_fd() const override { return scans_.folder ? scans_.folder->event_fd() : -1; }
  void read_events() override {
    if (scans_.folder) scans_.folder->read_events();
    if (hides_.folder) hides_.folder->read_events();  // tick() runs every 100 ms anyway
  }
  std::string stuck(Clock::time_point now) const override { return monitor_.stuck(now); }
  std::string status_line() const override;
  // As on a spool (station/config_reload.hpp): the batch rule, materials, cutter settings apply at
  // once; paths, workers, the set of cutters and [ledger] at the next start (the line says so).
  std::string reload(std::shared_ptr<const DaemonConfig> config) override;
  void stop() override;

 private:
  // The [ledger] table as started: a reload keeps it until restart (station/config_reload.hpp).
  const LedgerConfig& ledger() const { return ledger_; }
  // The running configuration; SIGHUP replaces it (any thread may read it).
  std::shared_ptr<const DaemonConfig> config() const { return config_.get(); }
  // One folder files are dropped into: the watch folder (scans) or the hides folder.
  struct Intake {
    std::string name;  // "watch folder", "hides folder"
    std::unique_ptr<HotFolder> folder;
    Status (LedgerNode::*enter)(const ReadyScan&) = nullptr;
    Clock::time_point next{};  // while the ledger or the share is away, the next try
    std::string trouble;       // as last logged
  };
  // scan_intake.cpp (main thread): scans and hides
  void take(const ReadyScan& ready, Intake& intake);
  Status enter(const ReadyScan& ready);
  Status enter_hide(const ReadyScan& ready);
  void refuse(const ReadyScan& ready, const std::string& reason);
  void sweep();
  // ledger_compute.cpp (one thread per jobs.compute_workers)
  void compute_worker(int index);
  void compute_job(ledger::LedgerClient& client, const ledger::JobClaim& claim, const std::string& worker);
  // ledger_nesting.cpp (compute threads): a strip batch, or the jobs waiting for a hide on that hide
  void nest_batch(ledger::LedgerClient& client, const ledger::BatchClaim& claim, const std::string& worker);
  Status nest_on_strip(const ledger::BatchClaim& claim, const MaterialConfig& material, const CutterSection& cutter,
                       const std::filesystem::path& scratch, ledger::NestedBatch& nested);
  Status nest_on_hide(const ledger::BatchClaim& claim, const MaterialConfig& material, const CutterSection& cutter,
                      const std::filesystem::path& scratch, ledger::NestedBatch& nested);
  // Logs and tells (MQTT) each claimed job how the nesting ended, in claim order; returns the jobs batched.
  std::size_t tell_job_outcomes(const ledger::BatchClaim& claim, const ledger::NestedBatch& nested);
  std::vector<std::string> hide_materials() const;
  // ledger_station.cpp: a CutterWorker for each cutter cabled here, its batches in the ledger
  void start_cutters(const std::vector<std::string>& cutters);
  void stop_cutters();
  int cuts_in_progress() const;
  // Worker threads: each has a connection of its own; false (after a pause) while none can be opened.
  bool connect_worker(std::unique_ptr<ledger::LedgerClient>& client, std::string& trouble, const std::string& worker);
  // Worker threads: waits up to `seconds` or until stop().
  void pause(double seconds);
  // One log line per change of a thread's trouble (the ledger away, a cutter not ready), not per try.
  void note_trouble(std::string& last, const std::string& now, const std::string& what);
  // What a job's change says once the ledger took it (the change itself is the fenced LedgerClient
  // call before it), the counterpart of a spool's set_job_stage: one log line "job N (scan): ..."
  // (an error when failed, a warning when held; none when neither `reason` nor `note` says
  // anything) and the job event for the status observer (MQTT) with its order, cutter, material
  // and batch. `reason`: why failed, held or waiting, also in the event; `note`: a log line only.
  void job_changed(long long job_id, const std::string& scan_name, const std::string& ticket_json, long long batch_id,
                   JobStage stage, const std::string& reason, const std::string& note = "");
  void batch_event(const ledger::BatchClaim& claim, JobStage stage, const std::string& reason);

  const LedgerConfig ledger_;
  RunningConfig config_;
  SharedStore store_;
  StatusObserver* observer_ = nullptr;
  Intake scans_{"watch folder", nullptr, &LedgerNode::enter};
  Intake hides_{"hides folder", nullptr, &LedgerNode::enter_hide};  // folder null when paths.hides is not set
  std::unique_ptr<ledger::LedgerClient> client_;  // main thread only
  std::unique_ptr<ledger::LeaseKeeper> keeper_;
  ProgressMonitor monitor_;
  std::vector<std::thread> threads_;
  std::atomic<bool> stopping_{false};
  std::mutex pause_mutex_;
  std::condition_variable pause_wake_;
  // One per cutter cabled here: its batches in the ledger and the worker that cuts them.
  struct Cutter {
    std::unique_ptr<LedgerCutStore> store;
    std::unique_ptr<CutterWorker> worker;
  };
  std::map<std::string, Cutter> cutters_;
  std::mutex ledger_condition_mutex_;
  bool ledger_down_ = false;  // as last logged by note_trouble(), for the whole node

  // Cutters whose batch this node's previous run left in `sending` (now held): their first state.
  // Written by start() before the station threads start, read-only afterwards.
  std::map<std::string, CutterStatus> held_at_start_;

  // Main thread only.
  Clock::time_point next_sweep_{};
  std::string sweep_trouble_;
  long long entered_ = 0, duplicates_ = 0, refused_ = 0;
};

}  // namespace lastcut::daemon
