#include "engine/nest/hide_merge.hpp"

#include <algorithm>

#include "engine/nest/nest_random.hpp"

namespace lastcut::nest_detail {

MergeTurn merge_turn(const NestInstance& instance, const HidePieces& pieces, const std::vector<int>& slot_of,
                     const std::vector<int>& order, long turn, double max_fill) {
  auto usable = [&](int slot) { return pieces.slots[slot].container->usable_area_mm2(); };
  auto cost = [&](int slot) { return instance.bins[pieces.slots[slot].bin_index].cost; };
  std::vector<double> placed(pieces.slots.size(), 0);
  double placed_sum = 0, used_sum = 0;
  for (size_t i = 0; i < slot_of.size(); ++i) {
    if (slot_of[i] < 0) continue;
    const double area = pieces.frames[0][pieces.item_of[i]].area_mm2;
    placed[slot_of[i]] += area;
    placed_sum += area;
  }
  for (int slot : order) used_sum += usable(slot);
  std::vector<MergeTurn> candidates;
  for (size_t a = 0; a < order.size(); ++a)
    for (size_t b = a + 1; b < order.size(); ++b) {
      MergeTurn t;
      t.first = order[a], t.second = order[b];
      if (placed[t.second] < placed[t.first]) std::swap(t.first, t.second);
      for (int slot = 0; slot < static_cast<int>(pieces.slots.size()); ++slot)  // the largest unused one
        if (std::find(order.begin(), order.end(), slot) == order.end() && cost(slot) <= cost(t.first) + cost(t.second) &&
            (t.spare < 0 || usable(slot) > usable(t.spare)))
          t.spare = slot;
      if (t.spare < 0) continue;
      t.fill_after = placed_sum / (used_sum - usable(t.first) - usable(t.second) + usable(t.spare));
      if (t.fill_after > max_fill) continue;
      for (int slot : order)
        if (slot != t.first && slot != t.second) t.destinations.push_back(slot);
      t.destinations.push_back(t.spare);
      candidates.push_back(std::move(t));
    }
  if (candidates.empty()) return {};
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const MergeTurn& x, const MergeTurn& y) { return x.fill_after < y.fill_after; });
  return candidates[static_cast<size_t>(turn) % candidates.size()];
}

bool merge_hides(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options, const Deadline& deadline,
                 std::vector<int>& slot_of, std::vector<PieceState>& state, const MergeTurn& turn, std::uint64_t seed,
                 const EjectBudget& budget) {
  if (turn.first < 0) return false;
  // The first hide's pieces mostly find free spots on the spare; the second hide is the hard part:
  // it gets three times the ejections, two more destinations and twice the separation.
  EjectBudget deep = budget;
  deep.max_ejections *= 3, deep.destinations += 2, deep.stale *= 2;
  for (int hide : {turn.first, turn.second}) {
    const EjectResult result = eject_hide(instance, pieces, options, deadline, slot_of, state, hide, turn.destinations,
                                          stream_seed(seed, static_cast<std::uint64_t>(hide), 41),
                                          hide == turn.first ? budget : deep);
    if (result != EjectResult::Emptied) return false;
  }
  return true;
}

}  // namespace lastcut::nest_detail
