// The swap of the hide search: one unit of a little-filled hide (the attempt's hide) and a smaller
// unit of a hide at least as full change places, each by the insertion of hide_move_insert. The
// little-filled hide gets emptier by the difference of their areas (the swap neighbourhood of
// Fleszar & Hindi's variable neighbourhood search for bin packing, Computers & Operations Research 29, 2002).
#include "engine/nest/hide_moves.hpp"
#include "engine/nest/nest_random.hpp"

namespace lastcut::nest_detail {

bool swap_units(HideSearchState& s, const MoveStep& step, const MoveContext& context) {
  const HidePieces& pieces = context.pieces;
  const std::vector<int> order = s.targets();
  const int target = attempt_target(order, step.attempt, context);
  const std::vector<int> target_units = s.units_on(target);
  const int unit = target_units[static_cast<size_t>(step.turn) % target_units.size()];
  // Partner: a hide at least as full holding a smaller unit whose place (plus its free area) the
  // larger one could take; the partners and their units in turn, largest smaller unit first.
  const double target_fill = s.fill(target), area = pieces.unit_area_mm2[unit];
  std::vector<std::pair<int, int>> candidates;  // (hide, unit)
  for (int slot : order) {
    if (slot == target || s.fill(slot) < target_fill) continue;
    for (int v : s.units_on(slot))
      if (pieces.unit_area_mm2[v] < area && s.free_area_mm2(slot) + pieces.unit_area_mm2[v] >= area) candidates.emplace_back(slot, v);
  }
  if (candidates.empty()) return false;
  const auto [partner, other] = candidates[static_cast<size_t>(step.turn) % candidates.size()];
  s.take_off(unit);
  s.take_off(other);
  return insert_unit(s, unit, partner, stream_seed(step.seed, 1, 5), step.effort, context) &&
         insert_unit(s, other, target, stream_seed(step.seed, 2, 5), step.effort, context);
}

}  // namespace lastcut::nest_detail
