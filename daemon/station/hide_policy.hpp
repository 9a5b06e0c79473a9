#pragma once
// When a hide that lies on a cutter's table is nested, and which waiting jobs go on it: the same
// rule on a spool and on the shop's ledger (docs/hides.md).
//  - A loaded hide waits for work: it is nested once a computed job of its material waits and
//    either no job of that material is still being computed or the hide has waited [batch]
//    window_s. A hide loaded while no job waits is not closed as empty; it stays on its table.
//  - At most kHideMaxJobs jobs are offered to one hide, oldest first (a hide of 5 m^2 holds about
//    40 pairs of molds); the rest wait for the next hide.
//  - The nester places higher priorities first: the sidecar's priority decides, then age.
#include <cstddef>

namespace lastcut::daemon {

inline constexpr int kHideMaxJobs = 64;

// Due to be nested now (see above).
inline bool hide_is_due(std::size_t computed_jobs_waiting, bool jobs_still_computing, double hide_waited_s,
                        double window_s) {
  return computed_jobs_waiting > 0 && (!jobs_still_computing || hide_waited_s >= window_s);
}

// The nesting priority of the job at `index` of `count` offered jobs, oldest first, whose ticket
// asks for `ticket_priority`: the ticket's priority first, then the oldest.
inline int hide_job_priority(int ticket_priority, std::size_t index, std::size_t count) {
  return ticket_priority * 100000 + static_cast<int>(count - index);
}

}  // namespace lastcut::daemon
