#pragma once
// What the batching tests (batching_policy_test.cpp, strip_batcher_test.cpp) build their cases from:
// a rule by window and pieces, and the job ids of each due batch.
#include <string>
#include <vector>

#include "daemon/station/batching_policy.hpp"

namespace lastcut::daemon::testing {

using Ids = std::vector<std::vector<std::string>>;

inline BatchConfig rule(double window_s, int max_pieces) {
  BatchConfig config;
  config.window_s = window_s;
  config.max_pieces = max_pieces;
  return config;
}

inline Ids ids_of(const std::vector<DueBatch>& batches) {
  Ids ids;
  for (const DueBatch& batch : batches) ids.push_back(batch.job_ids);
  return ids;
}

}  // namespace lastcut::daemon::testing
