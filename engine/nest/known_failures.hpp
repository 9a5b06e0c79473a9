#pragma once
// What the regrouping (hide_regroup.hpp) has learnt about hides that could not hold a set of units:
// a hide that cannot hold some units cannot hold them and more, so a superset of a failed set is
// known to fail without asking the packing oracle again, as long as the failed question was asked
// at least as long (a longer question may pack what a short one missed).
#include <cstddef>
#include <utility>
#include <vector>

namespace lastcut::nest_detail {

class KnownFailures {
 public:
  explicit KnownFailures(size_t hides = 0) : failed_(hides) {}

  // `units` (sorted ascending) did not all fit on `hide` with a question of `effort`.
  void add(size_t hide, const std::vector<int>& units, int effort);
  // `units` on `hide` is being asked again, longer: its old answer no longer stands for its supersets.
  void forget(size_t hide, const std::vector<int>& units);
  // A failed set on `hide` contained in `units` (sorted ascending) whose question had at least
  // `effort`, or nullptr when there is none (then only the oracle can tell).
  const std::vector<int>* failed_subset(size_t hide, const std::vector<int>& units, int effort) const;

 private:
  std::vector<std::vector<std::pair<std::vector<int>, int>>> failed_;  // per hide: (units, effort)
};

}  // namespace lastcut::nest_detail
