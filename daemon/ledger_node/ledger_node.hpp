#pragma once
// LedgerNode: the store of one node of a shop sharing a PostgreSQL job ledger (docs/multi-station.md,
// station/station_store.hpp), what the Station (station/station.hpp) runs when the configuration
// has [ledger], in place of the single station's SpoolStore.
//
//   watch folder --take_scan (main thread)--> shared/scans/<sha> + ledger job `ready`
//   hides folder --take_hide (main thread)--> shared/hides/<sha> + ledger hide `loaded` on its cutter
//   compute role: the station's ComputePool (the spool's, against LedgerComputeStore):
//                 claim job (lease) -> molds into shared/jobs/<sha> -> `computed`
//                 group computed jobs ([batch] window_s, max_pieces) -> nest -> shared/batches/<id> -> `queued`
//                 a loaded hide + the computed jobs of its material -> nest on it -> shared/batches/<id> -> `queued`
//                 (the jobs that did not fit: `computed` again, waiting for the next hide, with the reason)
//   station role: a CutterWorker per cutter cabled here (the spool's, against LedgerCutStore):
//                 claim its queued batch -> `sending` -> cut | held | queued again
//
// Every claim holds a lease the LeaseKeeper thread renews; a state change is fenced by the lease's
// epoch, so a node that lost a claim (a long pause, a cut network) only drops its work. The main
// thread sweeps expired leases of any node each heartbeat: what a vanished node computed is
// redone elsewhere, what it was sending is held, never re-sent (at most once, as on one station);
// and once a minute the batch folders no ledger row uses any more (orphan_sweep.hpp).
// The database away: intake leaves scans in the watch folder, workers retry, a cut in progress
// finishes and its end is written when the ledger is back; each change of condition is one log line.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "daemon/config/daemon_config.hpp"
#include "daemon/ledger/lease_keeper.hpp"
#include "daemon/ledger/ledger_client.hpp"
#include "daemon/ledger_node/ledger_compute_store.hpp"
#include "daemon/ledger_node/ledger_cut_store.hpp"
#include "daemon/ledger_node/ledger_journal.hpp"
#include "daemon/ledger_node/shared_store.hpp"
#include "daemon/station/config_reload.hpp"
#include "daemon/station/station_store.hpp"
#include "daemon/job/status_observer.hpp"
#include "daemon/job/job_ticket.hpp"

namespace lastcut::daemon {

class LedgerNode : public StationStore {
 public:
  explicit LedgerNode(const RunningConfig& config);
  ~LedgerNode() override;
  LedgerNode(const LedgerNode&) = delete;
  LedgerNode& operator=(const LedgerNode&) = delete;

  // Connects, migrates the schema, registers the node and its cutters (handing back what an earlier
  // run left).
  Status open(const StationLinks& links) override;
  ComputeStore* compute_store() override { return compute_store_.get(); }
  // Other nodes' work cannot wake this node's workers: they ask the ledger again every 0.25 s.
  ComputePoolTiming compute_timing() const override { return {0.25, ledger_.heartbeat_s}; }
  std::vector<StationCutter> cutters() override;
  // scan_intake.cpp: Later while the ledger or the shared folder is away (one log line per change).
  Intake take_scan(const ReadyScan& ready) override;
  Intake take_hide(const ReadyScan& ready) override;
  // The sweep of expired leases each heartbeat.
  void tick(Clock::time_point now) override;
  std::string where() const override;
  std::string status_line() const override;
  void stopping() override;
  void close() override;

 private:
  // The [ledger] table as started: a reload keeps it until restart (station/config_reload.hpp).
  const LedgerConfig& ledger() const { return ledger_; }
  // The running configuration; SIGHUP replaces it (any thread may read it).
  std::shared_ptr<const DaemonConfig> config() const { return config_.get(); }
  // One folder files are dropped into: the watch folder (scans) or the hides folder.
  struct DropFolder {
    std::string name;  // "watch folder", "hides folder"
    Status (LedgerNode::*enter)(const ReadyScan&) = nullptr;
    std::string trouble;  // as last logged
  };
  // scan_intake.cpp (main thread): scans and hides
  Intake take(const ReadyScan& ready, DropFolder& folder);
  Status enter(const ReadyScan& ready);
  Status enter_hide(const ReadyScan& ready);
  void refuse(const ReadyScan& ready, const std::string& reason);
  void sweep();
  // ledger_station.cpp: a store of batches for each cutter cabled here
  void open_cutters(const std::vector<std::string>& cutters);
  // Worker threads: waits up to `seconds` or until stop().
  void pause(double seconds);
  // One log line per change of a thread's trouble (the ledger away, a cutter not ready), not per try.
  void note_trouble(std::string& last, const std::string& now, const std::string& what);
  const RunningConfig& config_;
  const LedgerConfig ledger_;
  SharedStore store_;
  StationLinks links_;
  DropFolder scans_{"watch folder", &LedgerNode::enter, ""};
  DropFolder hides_{"hides folder", &LedgerNode::enter_hide, ""};
  std::unique_ptr<ledger::LedgerClient> client_;  // main thread only
  std::unique_ptr<LedgerJournal> journal_;  // every job change of this node (made by open())
  std::unique_ptr<ledger::LeaseKeeper> keeper_;
  std::unique_ptr<LedgerComputeStore> compute_store_;  // null without the compute role
  std::atomic<bool> stopping_{false};
  std::mutex pause_mutex_;
  std::condition_variable pause_wake_;
  // Each cutter cabled here: its batches in the ledger (cut by the station's worker).
  std::map<std::string, std::unique_ptr<LedgerCutStore>> cutters_;
  std::mutex ledger_condition_mutex_;
  bool ledger_down_ = false;  // as last logged by note_trouble(), for the whole node

  // Cutters whose batch this node's previous run left in `sending` (now held): their first state.
  // Written by open() before the station threads start, read-only afterwards.
  std::map<std::string, CutterStatus> held_at_start_;

  // Main thread only.
  Clock::time_point next_sweep_{};
  std::string sweep_trouble_;
  Clock::time_point next_orphan_sweep_{};
  std::string orphan_trouble_;
  long long entered_ = 0, duplicates_ = 0, refused_ = 0;
};

}  // namespace lastcut::daemon
