// The insertion of one unit onto a hide, which the moves of the hide search share, and the insert
// move of the knapsack form (a unit left over onto some hide). A free sampled spot first (sparrow's
// sampled placement with coordinate descent: Gardeyn, Vanden Berghe & Wauters, arXiv:2509.13329,
// 2025); otherwise the unit is dropped in, overlapping, and the hide separated by guided local search
// (Egeblad, Nielsen & Odgaard 2007) with the pole overlap proxy and parallel sweep workers.
#include <algorithm>

#include "engine/nest/hide_moves.hpp"
#include "engine/nest/nest_random.hpp"
#include "engine/nest/parallel_separation.hpp"

namespace lastcut::nest_detail {

bool insert_unit(HideSearchState& s, int unit, int slot, std::uint64_t seed, const Effort& effort, const MoveContext& context) {
  const HidePieces& pieces = context.pieces;
  const int samples = context.tuning.place_samples;
  const std::vector<int>& members = pieces.units[unit];
  for (int p : members)
    if (!pieces.fits_frame(p, slot)) return false;
  HidePlacement& a = s.edit();  // no cached figure is read below
  // A free sampled spot first (cheap); pair members as near the first one as the samples allow.
  std::vector<int> rest;
  for (size_t m = 0; m < members.size(); ++m) {
    const int p = members[m];
    Separator::Objective objective = [](const Box& b) { return b.x1 + 1e-3 * b.y0; };
    if (m > 0 && a.slot_of[members[0]] == slot) objective = near_piece(pieces, members[0], slot, a.state[members[0]]);
    if (!place_on_slot(pieces, p, slot, a.slot_of, a.state, objective, samples, stream_seed(seed, m, 1))) rest.push_back(p);
  }
  if (!rest.empty()) {
    // Drop the rest in and separate the hide: at the hide's centre at first, at a random pose and
    // spot once the plain attempts failed (another start, another outcome of the separation).
    Random random(stream_seed(seed, 0, 9));
    std::vector<int> local;
    for (size_t i = 0; i < a.slot_of.size(); ++i)
      if (a.slot_of[i] == slot) local.push_back(static_cast<int>(i));
    std::vector<const PreparedItem*> prepared;
    std::vector<PieceState> start;
    for (int p : local) prepared.push_back(&pieces.prepared(p, slot)), start.push_back(a.state[p]);
    const HideContainer& container = *pieces.slots[slot].container;
    for (int p : rest) {
      const PreparedItem& item = pieces.prepared(p, slot);
      PieceState st{0, container.offset_range(item.orientations[0]).centre()};
      if (effort.level > 0) {
        st.orientation = random.below(static_cast<int>(item.orientations.size()));
        const Box range = container.offset_range(item.orientations[st.orientation]);
        st.offset = {random.uniform(range.x0, range.x1), random.uniform(range.y0, range.y1)};
      }
      if (a.slot_of[members[0]] == slot) st.offset = a.state[members[0]].offset;  // next to its pair
      local.push_back(p);
      prepared.push_back(&item);
      start.push_back(st);
    }
    const NestOptions& options = context.options;
    ParallelSeparation separation(prepared, container, seed, std::min(context.tuning.sweep_workers, options.sweep_workers),
                                  options.threads, options.run_parallel);
    separation.set_state(start);
    if (!separation.separate(effort.strikes, effort.stale_sweeps, context.deadline)) return false;
    for (size_t k = 0; k < local.size(); ++k) a.slot_of[local[k]] = slot, a.state[local[k]] = separation.state()[k];
  }
  // Pairs on this hide must still be near each other: re-place a stray piece next to its first one.
  for (int u : s.units_on(slot)) {
    if (unit_near(pieces, context.instance, u, slot, a.state)) continue;
    const std::vector<int>& group = pieces.units[u];
    for (size_t m = 1; m < group.size(); ++m) {
      const Separator::Objective near_first = near_piece(pieces, group[0], slot, a.state[group[0]]);
      const int old_slot = a.slot_of[group[m]];
      const PieceState old_state = a.state[group[m]];
      a.slot_of[group[m]] = -1;
      if (!place_on_slot(pieces, group[m], slot, a.slot_of, a.state, near_first, 2 * samples, stream_seed(seed, m, 3)))
        a.slot_of[group[m]] = old_slot, a.state[group[m]] = old_state;
    }
    if (!unit_near(pieces, context.instance, u, slot, a.state)) return false;
  }
  return true;
}

bool insert_anywhere(HideSearchState& s, int unit, const std::vector<int>& destinations, std::uint64_t seed,
                     const Effort& effort, const MoveContext& context) {
  int tried = 0;
  for (int slot : destinations) {
    if (s.free_area_mm2(slot) < context.pieces.unit_area_mm2[unit]) continue;
    HideSearchState trial = s;
    if (insert_unit(trial, unit, slot, stream_seed(seed, static_cast<std::uint64_t>(slot), 5), effort, context)) {
      s = std::move(trial);
      return true;
    }
    if (++tried == effort.destinations || context.deadline.passed()) break;
  }
  return false;
}

bool insert_left_over(HideSearchState& s, int unit, std::uint64_t seed, const MoveContext& context) {
  // The used hides, most free area first; failing those, the unused hides in opening order. Each
  // list gets its own tries: behind the used hides' limit an unused hide was never reached, and a
  // unit the greedy start left over stayed off for good (Test6, seed 6: 42 of 43 pieces placed).
  const std::vector<int> used = s.used_slots();
  std::vector<int> destinations = used, unused;
  std::stable_sort(destinations.begin(), destinations.end(), [&](int a, int b) { return s.free_area_mm2(a) > s.free_area_mm2(b); });
  for (int slot = 0; slot < static_cast<int>(context.pieces.slots.size()); ++slot)
    if (std::find(used.begin(), used.end(), slot) == used.end()) unused.push_back(slot);
  const Effort first_level = effort_at(0, context.tuning);
  return insert_anywhere(s, unit, destinations, seed, first_level, context) ||
         insert_anywhere(s, unit, unused, seed, first_level, context);
}

}  // namespace lastcut::nest_detail
