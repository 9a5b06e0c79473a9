// The re-pack of the hide search: a little-filled hide (the attempt's hide) and a fuller one packed
// again by the greedy (engine/nest/hide_repack), the fuller one first, the units of both in a
// perturbed largest-first order; kept when the concentration grows (the iterated greedy on two
// hides, no separation: cheap next to the insertions).
#include "engine/nest/hide_greedy.hpp"
#include "engine/nest/hide_moves.hpp"
#include "engine/nest/hide_repack.hpp"
#include "engine/nest/nest_random.hpp"

namespace lastcut::nest_detail {

bool repack_pair(HideSearchState& s, const MoveStep& step, const MoveContext& context) {
  const std::vector<int> order = s.targets();
  const int target = attempt_target(order, step.attempt, context);
  const double before = s.concentration(), target_fill = s.fill(target);
  std::vector<int> partners;
  for (int slot : order)
    if (slot != target && s.fill(slot) >= target_fill) partners.push_back(slot);
  if (partners.empty()) return false;
  const int partner = partners[static_cast<size_t>(step.turn) % partners.size()];
  std::vector<int> units = s.units_on(partner);
  for (int u : s.units_on(target)) units.push_back(u);
  Random random(stream_seed(step.seed, 0, 13));
  units = perturbed_order(context.pieces, units, random, false);
  HidePlacement& a = s.edit();
  if (!repack_hides(context.instance, context.pieces, a.slot_of, a.state, {partner, target}, units, step.seed)) return false;
  return s.concentration() > before * (1 + 1e-9);
}

}  // namespace lastcut::nest_detail
