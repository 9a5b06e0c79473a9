#pragma once
// CutStore: what a cutter worker (cutter_worker.hpp) needs from the store that keeps the batches:
// the spool of one station (daemon/spool_store/spool_cut_store.hpp) or the shop's PostgreSQL ledger
// (daemon/ledger_node/ledger_cut_store.hpp). The worker owns the order of things and the policy
// (probe, claim, the point of no return, how a send outcome becomes a batch state); the store owns
// persistence and claiming. A fake store stands in for both in tests/station/cutter_worker_test.cpp.
//
// Cutting is AT MOST ONCE: once mark_sending() has returned success, the batch ends Cut or Held,
// never queued again by itself.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "drivers/cutter.hpp"
#include "engine/core/status.hpp"

namespace lastcut::daemon {

// A batch claimed for one cutter.
struct CutOrder {
  std::string batch_id;
  std::filesystem::path cut_file;  // absolute; sent exactly as stored
  std::string cut_file_name;       // as an operator finds it (the name in the batch folder or shared folder)
  std::string job_name;            // what the cutter shows for the program (at most 16 characters)
  std::size_t jobs = 0;
  int pieces = 0;
};

// How a cut ended, as the batch's next state.
enum class CutEnd {
  Cut,      // the machine reported the program finished: the batch and its jobs are done
  NotSent,  // the driver guarantees nothing reached the machine: queued again and retried
  Held,     // maybe partly cut (fault, stop, crash), or nothing to send: an operator decides
};
std::string to_string(CutEnd end);

// The driver's send outcome as a batch state: the one place this mapping is made (as the CUPS
// scheduler maps a backend's exit status to a job state in one place).
CutEnd cut_end_of(drivers::SendOutcome outcome);

class CutStore {
 public:
  virtual ~CutStore() = default;

  // The batch next in line for this cutter, named in the cutter's status while the cutter is not
  // ready: "" when one may wait but the store cannot name it without a round trip (a ledger shared
  // with other nodes), nullopt when none waits. The worker probes the cutter only when a batch may
  // wait. Must be cheap.
  virtual std::optional<std::string> next_batch() = 0;
  // Claims this cutter's oldest queued batch: nullopt when none waits, an error line when the store
  // cannot be asked now (the worker logs it once per change and asks again later).
  virtual Result<std::optional<CutOrder>> claim() = 0;
  // The point of no return, written durably before the first byte. On failure nothing is sent and
  // the store decides whether the batch comes again (the spool puts it back first in line; a ledger
  // node whose lease was lost lets it go to whoever holds it now).
  virtual Status mark_sending(const CutOrder& order) = 0;
  // Writes the batch's end and its jobs' ends durably: `reason` says why (NotSent, Held), and
  // `cutter_answer` is what the machine said, kept in the jobs' reports. Returns the end recorded:
  // NotSent becomes Held when the batch cannot be put back in the queue (it would stay `sending`,
  // which recovery holds without saying why). Failures are logged and noted in the jobs' reports.
  virtual CutEnd record_end(const CutOrder& order, CutEnd end, const std::string& reason,
                            const std::vector<std::string>& cutter_answer) = 0;
};

}  // namespace lastcut::daemon
