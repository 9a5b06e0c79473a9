#include "daemon/station/batching_policy.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace lastcut::daemon {

std::vector<DueBatch> due_batches(const std::vector<WaitingJob>& waiting, const BatchConfig& rule, bool force) {
  if (rule.window_s <= 0) {
    // No window: each job alone, at once, however many wait together (a ledger node's worker may
    // find several computed at once; a spool's tick may bring several).
    std::vector<DueBatch> alone;
    for (const WaitingJob& job : waiting) alone.push_back({job.material, job.cutter, {job.id}, std::max(1, job.pieces)});
    return alone;
  }
  struct Open {
    DueBatch batch;
    double oldest_waited_s = 0;
    std::size_t first_seen = 0;  // the order of groups: where their oldest job stands
  };
  std::map<std::pair<std::string, std::string>, Open> open;
  std::vector<std::pair<std::size_t, DueBatch>> due;
  for (std::size_t i = 0; i < waiting.size(); ++i) {
    const WaitingJob& job = waiting[i];
    auto [it, inserted] = open.try_emplace({job.material, job.cutter});
    Open& group = it->second;
    if (group.batch.job_ids.empty()) {
      group.batch.material = job.material;
      group.batch.cutter = job.cutter;
      group.oldest_waited_s = job.waited_s;
      group.first_seen = i;
    }
    group.batch.job_ids.push_back(job.id);
    group.batch.pieces += std::max(1, job.pieces);
    if (rule.max_pieces > 0 && group.batch.pieces >= rule.max_pieces) {
      due.emplace_back(group.first_seen, std::move(group.batch));
      group = Open{};
    }
  }
  for (auto& [key, group] : open) {
    if (group.batch.job_ids.empty()) continue;
    if (force || group.oldest_waited_s >= rule.window_s) due.emplace_back(group.first_seen, std::move(group.batch));
  }
  std::stable_sort(due.begin(), due.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<DueBatch> batches;
  for (auto& [order, batch] : due) batches.push_back(std::move(batch));
  return batches;
}

}  // namespace lastcut::daemon
