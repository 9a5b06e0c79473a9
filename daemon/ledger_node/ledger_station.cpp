// The station role of a ledger node: a LedgerCutStore for each cutter cabled here, cut by the
// station's CutterWorker (daemon/station/cutter_worker.hpp, the same worker a spool station runs).
// The worker probes the cutter, claims the cutter's oldest queued batch only when it answers, marks
// it `sending` before the first byte (fenced by the lease), sends exactly the cut file of the
// shared folder, then records the end its outcome maps to.
#include "daemon/ledger_node/ledger_node.hpp"

namespace lastcut::daemon {

void LedgerNode::open_cutters(const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    cutters_[name] = std::make_unique<LedgerCutStore>(
        name, ledger(), store_, *keeper_,
        [this](double seconds) {
          pause(seconds);
          return !stopping_.load();
        },
        *journal_);
  }
}

std::vector<StationCutter> LedgerNode::cutters() {
  std::vector<StationCutter> places;
  for (const auto& [name, store] : cutters_) {
    // A batch this station was sending when it died stays the cutter's news until its next batch.
    const auto held = held_at_start_.find(name);
    places.push_back({name, store.get(),
                      held != held_at_start_.end() ? held->second : CutterStatus{name, "idle", "", "", 0, 0, 0, 0}});
  }
  return places;
}

}  // namespace lastcut::daemon
