// The regrouping step of the hide search: once the best layout has kept its number of hides for a
// while, its units regrouped onto one hide fewer (engine/nest/hide_regroup: which units go on which
// hide searched as bin packing, each hide's packing asked of the hide search on that hide alone).
// The moves carry one unit at a time between packed hides and stall where the pieces are large next
// to the hides (Baldacci Test6 stayed on 11 hides whatever the seed; regrouped, 10); with many small
// units a hide (shoe batches) the moves do well and each per-hide search is long, so it is not tried.
#include <algorithm>
#include <numeric>

#include "engine/nest/hide_moves.hpp"
#include "engine/nest/nest_random.hpp"

namespace lastcut::nest_detail {

std::optional<HidePlacement> regroup_fewer(const HideSearchState& s, long round, const MoveContext& context,
                                           const HidePackingOracle& oracle) {
  const HidePieces& pieces = context.pieces;
  const HideSearchTuning& tuning = context.tuning;
  const std::vector<int> used = s.used_slots();
  if (s.any_left_over() || used.size() < 2 || used.size() - 1 < s.area_bound()) return std::nullopt;
  std::vector<int> targets(used.size() - 1);
  std::iota(targets.begin(), targets.end(), 0);  // slots are in opening order: cheapest, then largest
  double placed = 0, usable = 0;
  for (int slot : used) placed += s.placed_area_mm2(slot);
  for (int slot : targets) usable += s.usable_area_mm2(slot);
  if (placed > tuning.regroup_fill * usable) return std::nullopt;
  // Many small units a hide: the moves do well there, and each per-hide search is long (shoe batches).
  const long units = std::count_if(pieces.units.begin(), pieces.units.end(),
                                   [&](const std::vector<int>& u) { return s.slot_of()[static_cast<size_t>(u.front())] >= 0; });
  if (units > tuning.regroup_units_per_hide * static_cast<long>(targets.size())) return std::nullopt;
  const Deadline& deadline = context.deadline;
  const Deadline slice(std::min(deadline.seconds_left(), std::max(tuning.regroup_min_s, tuning.regroup_time_share * deadline.seconds_left())));
  return regroup_onto(context.instance, pieces, context.options, s.slot_of(), targets, slice, RegroupBudget{},
                      stream_seed(context.options.seed, static_cast<std::uint64_t>(round), 29), oracle);
}

}  // namespace lastcut::nest_detail
