#pragma once
// LedgerComputeStore: the compute pool's store on a ledger node (station/compute_store.hpp). A
// worker's claim, in this order: a ready job (its molds); else a hide lying on a cutter's table
// with the computed jobs of its material (make_hide_batch: the cutter and its operator wait for
// it); else a strip batch the station's batching rule finds due (make_batch). The ledger groups the
// batch inside its own transaction, so nodes sharing it never form two batches of one job.
//
// Every claim holds a lease the LeaseKeeper renews. The work is written into a scratch folder of
// the shared folder and published (renamed into place) before the ledger hears of it, and the
// ledger only takes the outcome from the node that still holds the lease (fencing): a lost claim
// costs work, never a wrong state. Every change goes through the node's LedgerJournal.
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "daemon/config/daemon_config.hpp"
#include "daemon/config/ledger_config.hpp"
#include "daemon/job/job_state.hpp"
#include "daemon/ledger/lease_keeper.hpp"
#include "daemon/ledger/ledger_client.hpp"
#include "daemon/ledger_node/ledger_journal.hpp"
#include "daemon/ledger_node/shared_store.hpp"
#include "daemon/station/compute_store.hpp"

namespace lastcut::daemon {

class LedgerComputeStore : public ComputeStore {
 public:
  LedgerComputeStore(const LedgerConfig& ledger, const SharedStore& shared, ledger::LeaseKeeper& keeper,
                     std::function<std::shared_ptr<const DaemonConfig>()> settings, const LedgerJournal& journal,
                     LedgerJournal::Pause pause);

  Result<std::optional<ComputeClaim>> claim(const std::string& worker) override;

 private:
  std::unique_ptr<MoldsClaim> open_job(ledger::LedgerClient& client, ledger::JobClaim claim);
  std::unique_ptr<NestClaim> open_batch(ledger::LedgerClient& client, ledger::BatchClaim claim);

  const LedgerConfig& ledger_;
  const SharedStore& shared_;
  ledger::LeaseKeeper& keeper_;
  std::function<std::shared_ptr<const DaemonConfig>()> settings_;
  const LedgerJournal& journal_;
  LedgerJournal::Pause pause_;  // waits while finished work waits for the ledger
  std::mutex clients_mutex_;
  // Each worker's own connection, used by that worker's thread only.
  std::map<std::string, std::unique_ptr<ledger::LedgerClient>> clients_;
};

}  // namespace lastcut::daemon
