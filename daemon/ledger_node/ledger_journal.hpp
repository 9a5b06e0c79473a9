#pragma once
// LedgerJournal: the one way a job changes state on a ledger node, the counterpart of a spool's
// set_job_stage (spool_store/job_outcomes.hpp) and of cupsdSetJobState in the CUPS scheduler.
// change() runs the ledger call that saves the change (fenced by the lease where the node holds
// one, so a node that lost its claim cannot write) and, only when the ledger took it, says what
// changed: one log line per job, "job N (scan): ..." (an error when failed, a warning when held,
// none when neither reason nor note says anything), and a neutral JobEvent for the status
// observers (MQTT). Nothing is said of a change the ledger did not take; the caller decides what
// that costs (work dropped, a file left in the watch folder, a retry).
#include <functional>
#include <string>
#include <vector>

#include "daemon/job/job_state.hpp"
#include "daemon/job/job_ticket.hpp"
#include "daemon/job/status_observer.hpp"
#include "daemon/ledger/ledger_client.hpp"
#include "engine/core/status.hpp"

namespace lastcut::daemon {

// One job's change as the ledger took it.
struct LedgerJobChange {
  long long job_id = 0;
  std::string scan_name;
  std::string ticket_json;  // the job's ticket as the ledger keeps it (JSON text)
  long long batch_id = 0;   // 0: in no batch
  JobStage stage = JobStage::Claimed;
  std::string reason;  // why failed, held or waiting; in the event too
  std::string note;    // what happened, for the log line only
};
using LedgerJobChanges = std::vector<LedgerJobChange>;

// The change of every job of a claimed batch.
LedgerJobChanges batch_job_changes(const ledger::BatchClaim& claim, JobStage stage, const std::string& reason);
// Jobs the ledger held itself (their station vanished while sending), found by the sweep or at start.
LedgerJobChanges held_job_changes(const std::vector<ledger::HeldJob>& jobs);

// A ticket as the intake stored it in the ledger (ticket_to_json); a row no lastcutd wrote is refused.
Result<JobTicket> ticket_from_ledger(const std::string& text);

class LedgerJournal {
 public:
  // The ledger call: what it changed, or why it changed nothing.
  using Save = std::function<Result<LedgerJobChanges>()>;

  // `observer` may be null (no [status] configured); it must outlive the journal.
  explicit LedgerJournal(StatusObserver* observer) : observer_(observer) {}

  // Waits up to the given seconds; false when the node stops meanwhile.
  using Pause = std::function<bool(double seconds)>;

  // Saves through `save`, then logs and tells each change it returns, in order. Any thread.
  Status change(const Save& save) const;
  // change() for finished work (computed molds, a nested batch, the end of a cut): while the
  // ledger is away it is tried again every `retry_s` (kept in memory meanwhile, its lease still
  // renewed by the caller) until the ledger answers: it lands, or the ledger refuses it (the lease
  // was lost meanwhile: fencing decides), or `pause` says the node stops (the work is then
  // dropped and redone elsewhere). The outage is one warning "<label>: ...", and one line when it
  // lands after it.
  Status change_once_reachable(const Save& save, const Pause& pause, double retry_s, const std::string& label) const;

 private:
  void tell(const LedgerJobChange& change) const;

  StatusObserver* observer_;
};

// A Save of a ledger call that answers only yes or no: `changes` once it is taken.
LedgerJournal::Save save_then(std::function<Status()> call, LedgerJobChanges changes);

}  // namespace lastcut::daemon
