#pragma once
// The station's rules as the ledger asks them inside the transaction that forms a batch: the
// batching rule (daemon/station/batching_policy.hpp) for LedgerClient::make_batch, the first due
// batch or none, and the hide rule (daemon/station/hide_policy.hpp) for make_hide_batch.
#include <string>
#include <vector>

#include "daemon/ledger/ledger_client.hpp"
#include "daemon/station/batching_policy.hpp"
#include "daemon/station/hide_policy.hpp"

namespace lastcut::daemon {

// `force`: every group is due now (tests that group at once).
inline ledger::BatchChooser ledger_batch_rule(const BatchConfig& rule, bool force = false) {
  return [rule, force](const std::vector<ledger::ComputedJob>& computed) {
    std::vector<WaitingJob> waiting;
    for (const ledger::ComputedJob& job : computed)
      waiting.push_back({std::to_string(job.job_id), job.material, job.cutter, job.pieces, job.waited_s});
    std::vector<long long> ids;
    const std::vector<DueBatch> due = due_batches(waiting, rule, force);
    if (!due.empty())
      for (const std::string& id : due.front().job_ids) ids.push_back(std::stoll(id));
    return ids;
  };
}

inline ledger::HideDue ledger_hide_rule(double window_s) {
  return [window_s](std::size_t computed_waiting, bool still_computing, double hide_waited_s) {
    return hide_is_due(computed_waiting, still_computing, hide_waited_s, window_s);
  };
}

}  // namespace lastcut::daemon
