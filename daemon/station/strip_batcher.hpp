#pragma once
// StripBatcher: the computed jobs of strip materials that wait on one station to be nested
// together, and when each started waiting. It asks the batching rule (batching_policy.hpp, the
// same function the ledger asks inside its transaction) which groups are due and hands them out
// once: a job handed out no longer waits. The clock is the caller's: every call takes `now`, so a
// test drives it with made-up times. Main thread only (no locking).
#include <chrono>
#include <string>
#include <vector>

#include "daemon/config/daemon_config.hpp"
#include "daemon/station/batching_policy.hpp"

namespace lastcut::daemon {

class StripBatcher {
 public:
  using Clock = std::chrono::steady_clock;

  // `job` (its id, material, cutter and pieces; waited_s is ignored) starts waiting at `now`. A job
  // already waiting keeps its place and its time.
  void add(const WaitingJob& job, Clock::time_point now);
  // The groups `rule` finds due at `now` (`force`: every group, as when a station stops), oldest
  // group first, taken out of the waiting list.
  std::vector<DueBatch> take_due(Clock::time_point now, const BatchConfig& rule, bool force = false);
  // Jobs waiting now.
  std::size_t waiting() const { return waiting_.size(); }

 private:
  struct Waiting {
    WaitingJob job;
    Clock::time_point since;
  };
  std::vector<Waiting> waiting_;  // oldest first
};

}  // namespace lastcut::daemon
