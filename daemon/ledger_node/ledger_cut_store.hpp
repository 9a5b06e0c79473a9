#pragma once
// LedgerCutStore: one cutter's batches in the shop's PostgreSQL ledger, for the CutterWorker of
// the node the cutter is cabled to (daemon/station/cutter_worker.hpp). A claim holds a lease the
// LeaseKeeper renews; every change is fenced by the lease's epoch, so a node that lost the claim
// (a long pause, a cut network) only drops it. The end of a cut is written again and again while
// the ledger is away, until it lands: a cut that happened is never forgotten, nor sent again.
// The cut file is read from the shared folder exactly as the nesting node wrote it.
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "daemon/config/ledger_config.hpp"
#include "daemon/job/job_state.hpp"
#include "daemon/ledger/lease_keeper.hpp"
#include "daemon/ledger/ledger_client.hpp"
#include "daemon/ledger_node/ledger_journal.hpp"
#include "daemon/ledger_node/shared_store.hpp"
#include "daemon/station/cut_store.hpp"

namespace lastcut::daemon {

class LedgerCutStore : public CutStore {
 public:
  // Waits up to the given seconds (or until the node stops: then false).
  using Pause = std::function<bool(double seconds)>;

  LedgerCutStore(std::string cutter, const LedgerConfig& ledger, const SharedStore& shared, ledger::LeaseKeeper& keeper,
                 Pause pause, const LedgerJournal& journal);

  // Other nodes nest this cutter's batches: one may always wait, unnamed until claimed.
  std::optional<std::string> next_batch() override { return std::string(); }
  Result<std::optional<CutOrder>> claim() override;
  Status mark_sending(const CutOrder& order) override;
  CutEnd record_end(const CutOrder& order, CutEnd end, const std::string& reason,
                    const std::vector<std::string>& cutter_answer) override;

 private:
  // Writes a change of the claimed batch through the journal (which then tells `changes`), again
  // while the ledger is away; false when it cannot land (the lease was lost, or the node stops).
  bool record(const std::function<Status()>& save, const LedgerJobChanges& changes);
  // The claim ends: its lease is no longer renewed.
  void let_go();

  std::string cutter_;
  const LedgerConfig& ledger_;
  const SharedStore& shared_;
  ledger::LeaseKeeper& keeper_;
  Pause pause_;
  const LedgerJournal& journal_;
  std::unique_ptr<ledger::LedgerClient> client_;  // this cutter's own connection (worker thread only)
  std::optional<ledger::BatchClaim> claimed_;
};

}  // namespace lastcut::daemon
