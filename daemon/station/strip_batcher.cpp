#include "daemon/station/strip_batcher.hpp"

#include <algorithm>
#include <set>

namespace lastcut::daemon {

void StripBatcher::add(const WaitingJob& job, Clock::time_point now) {
  const bool known = std::any_of(waiting_.begin(), waiting_.end(),
                                 [&](const Waiting& waiting) { return waiting.job.id == job.id; });
  if (!known) waiting_.push_back({job, now});
}

std::vector<DueBatch> StripBatcher::take_due(Clock::time_point now, const BatchConfig& rule, bool force) {
  std::vector<WaitingJob> jobs;
  for (const Waiting& waiting : waiting_) {
    WaitingJob job = waiting.job;
    job.waited_s = std::chrono::duration<double>(now - waiting.since).count();
    jobs.push_back(std::move(job));
  }
  std::vector<DueBatch> due = due_batches(jobs, rule, force);
  std::set<std::string> taken;
  for (const DueBatch& batch : due) taken.insert(batch.job_ids.begin(), batch.job_ids.end());
  std::erase_if(waiting_, [&](const Waiting& waiting) { return taken.count(waiting.job.id) != 0; });
  return due;
}

}  // namespace lastcut::daemon
