// The move of the hide search: one unit of a little-filled hide (the attempt's hide: the least filled
// first, the smaller hide on a tie, each for a few attempts) onto a hide at least as full, by the
// insertion of hide_move_insert (the one with the most free area first). The little-filled hide gets
// emptier, the fuller one fuller: a hide that loses its last unit is closed (bin-packing local search
// emptying the weakest bin: Lodi, Martello & Vigo, INFORMS Journal on Computing 11, 1999).
#include <algorithm>

#include "engine/nest/hide_moves.hpp"

namespace lastcut::nest_detail {

bool move_unit(HideSearchState& s, const MoveStep& step, const MoveContext& context) {
  const std::vector<int> order = s.targets();
  const int target = attempt_target(order, step.attempt, context);
  const std::vector<int> units = s.units_on(target);
  const int unit = units[static_cast<size_t>(step.turn) % units.size()];
  const double target_fill = s.fill(target);
  s.take_off(unit);
  std::vector<int> destinations;
  for (int slot : order)
    if (slot != target && s.fill(slot) >= target_fill) destinations.push_back(slot);
  std::stable_sort(destinations.begin(), destinations.end(), [&](int a, int b) { return s.free_area_mm2(a) > s.free_area_mm2(b); });
  return insert_anywhere(s, unit, destinations, step.seed, step.effort, context);
}

}  // namespace lastcut::nest_detail
