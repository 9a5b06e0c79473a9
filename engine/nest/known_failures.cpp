// Failed unit sets per hide and their supersets; see known_failures.hpp.
#include "engine/nest/known_failures.hpp"

#include <algorithm>

namespace lastcut::nest_detail {

void KnownFailures::add(size_t hide, const std::vector<int>& units, int effort) {
  forget(hide, units);
  failed_[hide].emplace_back(units, effort);
}

void KnownFailures::forget(size_t hide, const std::vector<int>& units) {
  std::erase_if(failed_[hide], [&](const auto& entry) { return entry.first == units; });
}

const std::vector<int>* KnownFailures::failed_subset(size_t hide, const std::vector<int>& units, int effort) const {
  for (const auto& [failed, failed_effort] : failed_[hide])
    if (failed_effort >= effort && std::includes(units.begin(), units.end(), failed.begin(), failed.end()))
      return &failed;
  return nullptr;
}

}  // namespace lastcut::nest_detail
