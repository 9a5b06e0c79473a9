// The shrink of the hide search: every unit of a used hide onto an unused smaller one, no dearer,
// that has room for their area (the `turn`-th such pair, the lowest resulting fill first), each by
// the insertion of hide_move_insert: the same pieces on less leather. The only move but the replacing
// chain left once the used hides are as few as their area allows.
#include <algorithm>

#include "engine/nest/hide_moves.hpp"
#include "engine/nest/nest_random.hpp"

namespace lastcut::nest_detail {

bool shrink_hide(HideSearchState& s, const MoveStep& step, const MoveContext& context) {
  const HidePieces& pieces = context.pieces;
  const std::vector<int> used = s.used_slots();
  auto cost = [&](int slot) { return context.instance.bins[pieces.slots[slot].bin_index].cost; };
  std::vector<std::pair<int, int>> candidates;  // (used hide, smaller unused hide)
  for (int from : used)
    for (int to = 0; to < static_cast<int>(pieces.slots.size()); ++to)
      if (std::find(used.begin(), used.end(), to) == used.end() && s.usable_area_mm2(to) < s.usable_area_mm2(from) &&
          s.usable_area_mm2(to) >= s.placed_area_mm2(from) && cost(to) <= cost(from))
        candidates.emplace_back(from, to);
  if (candidates.empty()) return false;
  // The likeliest first: the lowest fill the pieces would have on the smaller hide.
  std::stable_sort(candidates.begin(), candidates.end(), [&](const auto& a, const auto& b) {
    return s.placed_area_mm2(a.first) / s.usable_area_mm2(a.second) < s.placed_area_mm2(b.first) / s.usable_area_mm2(b.second);
  });
  const auto [from, to] = candidates[static_cast<size_t>(step.turn) % candidates.size()];
  const std::vector<int> units = s.units_on(from);
  for (int u : units) s.take_off(u);
  for (int u : units)
    if (!insert_unit(s, u, to, stream_seed(step.seed, static_cast<std::uint64_t>(u), 21), step.effort, context)) return false;
  return true;
}

}  // namespace lastcut::nest_detail
