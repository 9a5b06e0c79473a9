#pragma once
// LeaseKeeper: the heartbeat of a ledger node. A thread of its own, with its own connection,
// renews every lease the node works under each heartbeat_s, and the node's heartbeat row, so a
// long flattening or a long cut keeps its claim. A renewal the ledger refuses (another node holds
// the row now: fencing) marks the lease lost; the worker asks lost() and drops the job. When the
// database cannot be reached the keeper retries every retry_s() (never backing off: a database
// restart must not cost a live station its leases) and logs once per change ("leases not renewed,
// retrying: ...", "ledger reachable again"), never once per try. With the sweep's grace of one
// heartbeat (LedgerClient::sweep_expired), a lease survives an outage shorter than
// lease_s - retry_s (docs/multi-station.md).
#include <atomic>
#include <condition_variable>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>

#include "daemon/ledger/ledger_client.hpp"

namespace lastcut::ledger {

class LeaseKeeper {
 public:
  using Log = std::function<void(const std::string& line)>;  // one line per change of condition

  LeaseKeeper(std::string url, std::string node, double lease_s, double heartbeat_s, Log log);
  ~LeaseKeeper();  // stops the thread; kept leases simply run out
  LeaseKeeper(const LeaseKeeper&) = delete;
  LeaseKeeper& operator=(const LeaseKeeper&) = delete;

  void keep(const Lease& lease);  // renew from now on
  void drop(const Lease& lease);  // after the claim's last state change (or when giving it up)
  bool lost(const Lease& lease) const;  // a renewal was refused: another node holds the row now
  bool reachable() const { return reachable_; }
  // How often a renewal is tried again while the database is away: 1 s, or the heartbeat if shorter.
  double retry_s() const;

 private:
  void run();
  void beat(std::unique_ptr<LedgerClient>& client);

  std::string url_, node_;
  double lease_s_, heartbeat_s_;
  Log log_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::map<std::pair<int, long long>, Lease> kept_;  // by (kind, object)
  std::set<std::pair<int, long long>> lost_;
  std::atomic<bool> reachable_{true};
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace lastcut::ledger
