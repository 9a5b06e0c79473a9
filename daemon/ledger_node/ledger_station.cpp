// The station role of a ledger node: a CutterWorker (daemon/station/cutter_worker.hpp, the same
// worker a spool station runs) for each cutter cabled here, its batches claimed from the ledger
// through LedgerCutStore. The worker probes the cutter, claims the cutter's oldest queued batch
// only when it answers, marks it `sending` before the first byte (fenced by the lease), sends
// exactly the cut file of the shared folder, then records the end its outcome maps to.
#include <spdlog/spdlog.h>

#include "daemon/ledger_node/ledger_node.hpp"

namespace lastcut::daemon {

void LedgerNode::start_cutters(const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    Cutter& cutter = cutters_[name];
    cutter.store = std::make_unique<LedgerCutStore>(
        name, ledger(), store_, *keeper_, [this](double seconds) {
          pause(seconds);
          return !stopping_.load();
        },
        [this](const ledger::BatchClaim& claim, JobStage stage, const std::string& reason) {
          batch_event(claim, stage, reason);
        });
    cutter.worker = std::make_unique<CutterWorker>(name, *cutter.store, monitor_, [this, name] {
      const auto current = config();
      const auto it = current->cutters.find(name);
      return it != current->cutters.end() ? it->second : CutterSection{};
    });
    if (observer_) {
      cutter.worker->on_status([observer = observer_](const CutterStatus& status) { observer->cutter_changed(status); });
    }
    // A batch this station was sending when it died stays the cutter's news until its next batch.
    const auto held = held_at_start_.find(name);
    cutter.worker->start(held != held_at_start_.end() ? held->second : CutterStatus{name, "idle", "", "", 0, 0, 0, 0});
  }
}

void LedgerNode::stop_cutters() {
  // In parallel: each cutter gets the whole grace time for the cut in its hands; then the cut is
  // interrupted and its batch held.
  const double grace_s = config()->jobs.stop_grace_s;
  std::vector<std::thread> stopping;
  for (auto& [name, cutter] : cutters_) {
    stopping.emplace_back([&worker = *cutter.worker, grace_s] { worker.stop(grace_s); });
  }
  for (std::thread& thread : stopping) thread.join();
  cutters_.clear();
}

int LedgerNode::cuts_in_progress() const {
  int cutting = 0;
  for (const auto& [name, cutter] : cutters_) cutting += cutter.worker->cutting() ? 1 : 0;
  return cutting;
}

}  // namespace lastcut::daemon
