#pragma once
// StationStore: what a Station (station.hpp) needs from the store that keeps its jobs: the spool of
// one station (daemon/spool_store/spool_store.hpp) or a node of a shop on the PostgreSQL ledger
// (daemon/ledger_node/ledger_store.hpp). The station owns the order of things: the watch folders,
// the compute pool, the cutter workers, start and stop. The store owns persistence, claiming and
// leases, and what is store-shaped by nature: taking a file in (a spool claims it into work/, a
// ledger node enters it for the whole shop), grouping computed jobs into batches where the store
// does it outside a compute claim (the spool; the ledger groups inside make_batch), and putting
// right what an earlier run left (the spool's recovery, the ledger's sweep of expired leases).
#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "daemon/job/status_observer.hpp"
#include "daemon/station/compute_pool.hpp"
#include "daemon/station/compute_store.hpp"
#include "daemon/station/cut_store.hpp"
#include "daemon/watch/hot_folder.hpp"
#include "engine/core/status.hpp"

namespace lastcut::daemon {

// How a store reaches the station's parts, handed to open().
struct StationLinks {
  StatusObserver* observer = nullptr;                            // may be null
  std::function<void()> wake_compute;                            // new work in the compute store
  std::function<void(const std::string& cutter)> wake_cutter;    // a batch queued for this cutter
  std::function<std::string(const std::string& cutter)> cutter_condition;  // "idle", "cutting B (40 %)", ...
  std::function<std::size_t()> files_being_checked;              // in the watch folder, not yet stable
};

// One cutter this node cuts for.
struct StationCutter {
  std::string name;
  CutStore* store = nullptr;  // owned by the station store
  CutterStatus first;         // its state until its next batch (a batch held by an earlier run)
};

class StationStore {
 public:
  using Clock = std::chrono::steady_clock;
  // What became of a file offered to take_scan / take_hide.
  enum class Intake {
    Taken,  // in the store, or refused with its reason where an operator finds it
    Later,  // the store cannot take files now (the ledger away): it stays where it was dropped
  };

  virtual ~StationStore() = default;

  // Prepares the storage and puts right what an earlier run left, before any file is taken. One
  // line on failure.
  virtual Status open(const StationLinks& links) = 0;
  // This node's jobs and batches to compute; null when it does not compute (a ledger node without
  // the compute role).
  virtual ComputeStore* compute_store() = 0;
  // How often the compute workers ask it again (a store shared with other nodes cannot wake them).
  virtual ComputePoolTiming compute_timing() const = 0;
  // The cutters cabled to this node, each with its store of batches.
  virtual std::vector<StationCutter> cutters() = 0;
  // A ready scan from the watch folder, a ready hide file from the hides folder.
  virtual Intake take_scan(const ReadyScan& ready) = 0;
  virtual Intake take_hide(const ReadyScan& ready) = 0;
  // One turn of the main loop: whatever is due in the store (batches, hides, expired leases, the
  // status file).
  virtual void tick(Clock::time_point now) = 0;
  // "where": the store in a few words for the start line ("spool /var/spool/lastcut", "ledger node
  // n1 (compute+station), shared folder /mnt/shop").
  virtual std::string where() const = 0;
  // The store's part of the status line (queues, counts, the ledger's reachability).
  virtual std::string status_line() const = 0;
  // The node is stopping: end the store's own waits (a cut's end waiting for the ledger gives up).
  virtual void stopping() = 0;
  // After the workers stopped: unclaimed work stays in the store for the next start.
  virtual void close() = 0;
};

}  // namespace lastcut::daemon
