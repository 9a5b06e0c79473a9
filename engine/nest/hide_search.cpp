#include "engine/nest/hide_search.hpp"

#include <algorithm>
#include <numeric>

#include "engine/nest/hide_greedy.hpp"
#include "engine/nest/nest_random.hpp"
#include "engine/nest/parallel_separation.hpp"

namespace lastcut::nest_detail {
namespace {

// Separation budget of one insertion (strikes of `kStale` sweeps without a 2 % improvement) and the
// sweep workers of a hide's separation: a small budget tried often beat 3 x 40 sweeps and four
// workers on Test1, Test5 and Test6 at 10 s (docs/benchmarks-nest.md).
constexpr int kStrikes = 2, kStale = 15;
constexpr int kPlaceSamples = 240;
constexpr int kHideSweepWorkers = 2;
constexpr int kDestinations = 2;  // hides an inserted unit tries, most free area first
constexpr long kGiveUp = 12;      // failed moves in a row per used hide (and nothing left to insert): stop
constexpr long kPerTarget = 4;   // failed moves before the next hide is tried

Point2 box_centre(const Box& b) { return {0.5 * (b.x0 + b.x1), 0.5 * (b.y0 + b.y1)}; }

class HideSearch {
 public:
  HideSearch(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options)
      : instance_(instance), pieces_(pieces), options_(options), deadline_(options.time_limit_s) {}

  Layout run();

 private:
  struct State {
    std::vector<int> slot_of;
    std::vector<PieceState> state;
  };
  double placed_area(const State& s, int slot) const {
    double a = 0;
    for (size_t i = 0; i < s.slot_of.size(); ++i)
      if (s.slot_of[i] == slot) a += pieces_.frames[0][pieces_.item_of[i]].area_mm2;
    return a;
  }
  double free_area(const State& s, int slot) const {
    return pieces_.slots[slot].container->usable_area_mm2() - placed_area(s, slot);
  }
  std::vector<int> used_slots(const State& s) const {
    std::vector<int> used;
    for (int slot : s.slot_of)
      if (slot >= 0 && std::find(used.begin(), used.end(), slot) == used.end()) used.push_back(slot);
    std::sort(used.begin(), used.end());
    return used;
  }
  bool insert_unit(State& s, int unit, int slot, std::uint64_t seed);
  bool insert_anywhere(State& s, int unit, const std::vector<int>& destinations, std::uint64_t seed);
  Layout layout(const State& s, bool with_reasons) const {
    return finish_hides(instance_, pieces_, s.slot_of, s.state, with_reasons, options_.seed);
  }

  const NestInstance& instance_;
  const HidePieces& pieces_;
  const NestOptions& options_;
  Deadline deadline_;
};

bool HideSearch::insert_unit(State& s, int unit, int slot, std::uint64_t seed) {
  const std::vector<int>& members = pieces_.units[unit];
  for (int p : members)
    if (!pieces_.fits_frame(p, slot)) return false;
  // A free sampled spot first (cheap); pair members as near the first one as the samples allow.
  std::vector<int> rest;
  for (size_t m = 0; m < members.size(); ++m) {
    const int p = members[m];
    Separator::Objective objective = [](const Box& b) { return b.x1 + 1e-3 * b.y0; };
    if (m > 0 && s.slot_of[members[0]] == slot) {
      const PieceState& a = s.state[members[0]];
      const Point2 anchor = box_centre(pieces_.prepared(members[0], slot).orientations[a.orientation].box.shifted(a.offset));
      objective = [anchor](const Box& b) { return (box_centre(b) - anchor).norm(); };
    }
    if (!place_on_slot(pieces_, p, slot, s.slot_of, s.state, objective, kPlaceSamples, stream_seed(seed, m, 1)))
      rest.push_back(p);
  }
  if (!rest.empty()) {
    // Drop the rest in and separate the hide.
    std::vector<int> local;
    for (size_t i = 0; i < s.slot_of.size(); ++i)
      if (s.slot_of[i] == slot) local.push_back(static_cast<int>(i));
    std::vector<const PreparedItem*> prepared;
    std::vector<PieceState> start;
    for (int p : local) prepared.push_back(&pieces_.prepared(p, slot)), start.push_back(s.state[p]);
    for (int p : rest) {
      const PreparedItem& item = pieces_.prepared(p, slot);
      const Box range = pieces_.slots[slot].container->offset_range(item.orientations[0]);
      PieceState st{0, box_centre(range)};
      if (s.slot_of[members[0]] == slot) st.offset = s.state[members[0]].offset;  // next to its pair
      local.push_back(p);
      prepared.push_back(&item);
      start.push_back(st);
    }
    ParallelSeparation separation(prepared, *pieces_.slots[slot].container, seed, std::min(kHideSweepWorkers, options_.sweep_workers), options_.threads,
                                  options_.run_parallel);
    separation.set_state(start);
    if (!separation.separate(kStrikes, kStale, deadline_)) return false;
    for (size_t k = 0; k < local.size(); ++k) s.slot_of[local[k]] = slot, s.state[local[k]] = separation.state()[k];
  }
  // Pairs on this hide must still be near each other: re-place a stray piece next to its first one.
  std::vector<int> units_here;
  for (size_t i = 0; i < s.slot_of.size(); ++i)
    if (s.slot_of[i] == slot && std::find(units_here.begin(), units_here.end(), pieces_.unit_of[i]) == units_here.end())
      units_here.push_back(pieces_.unit_of[i]);
  for (int u : units_here) {
    if (unit_near(pieces_, instance_, u, slot, s.state)) continue;
    const std::vector<int>& group = pieces_.units[u];
    for (size_t m = 1; m < group.size(); ++m) {
      const PieceState& a = s.state[group[0]];
      const Point2 anchor = box_centre(pieces_.prepared(group[0], slot).orientations[a.orientation].box.shifted(a.offset));
      const int old_slot = s.slot_of[group[m]];
      const PieceState old_state = s.state[group[m]];
      s.slot_of[group[m]] = -1;
      if (!place_on_slot(pieces_, group[m], slot, s.slot_of, s.state,
                         [anchor](const Box& b) { return (box_centre(b) - anchor).norm(); }, 2 * kPlaceSamples,
                         stream_seed(seed, m, 3)))
        s.slot_of[group[m]] = old_slot, s.state[group[m]] = old_state;
    }
    if (!unit_near(pieces_, instance_, u, slot, s.state)) return false;
  }
  return true;
}

bool HideSearch::insert_anywhere(State& s, int unit, const std::vector<int>& destinations, std::uint64_t seed) {
  int tried = 0;
  for (int slot : destinations) {
    if (free_area(s, slot) < pieces_.unit_area_mm2[unit]) continue;
    State trial = s;
    if (insert_unit(trial, unit, slot, stream_seed(seed, static_cast<std::uint64_t>(slot), 5))) {
      s = std::move(trial);
      return true;
    }
    if (++tried == kDestinations || deadline_.passed()) break;
  }
  return false;
}

Layout HideSearch::run() {
  const HideAssignment start = greedy_hides(instance_, pieces_, unit_order_by_value(pieces_), stream_seed(options_.seed, 0, 0));
  State best{start.slot_of, start.state};
  if (options_.on_improvement) options_.on_improvement(layout(best, false));
  const int n_slots = static_cast<int>(pieces_.slots.size());
  long streak = 0;  // failed moves in a row
  std::vector<char> tried(pieces_.units.size(), 0);
  const std::vector<int> by_value = unit_order_by_value(pieces_);
  for (long round = 1; !options_.iteration_limit || round <= *options_.iteration_limit; ++round) {
    if (deadline_.passed()) break;
    const std::uint64_t seed = stream_seed(options_.seed, static_cast<std::uint64_t>(round), 0);
    const std::vector<int> used = used_slots(best);
    State trial = best;
    bool success = false;
    // Knapsack: a unit left over, most valuable first.
    int left_over = -1;
    for (int u : by_value)
      if (!tried[u] && best.slot_of[pieces_.units[u].front()] < 0) {
        left_over = u;
        break;
      }
    if (left_over >= 0) {
      std::vector<int> destinations = used;
      std::stable_sort(destinations.begin(), destinations.end(),
                       [&](int a, int b) { return free_area(best, a) > free_area(best, b); });
      for (int slot = 0; slot < n_slots; ++slot)
        if (std::find(used.begin(), used.end(), slot) == used.end()) {
          destinations.push_back(slot);
          break;
        }
      success = insert_anywhere(trial, left_over, destinations, seed);
      if (!success) tried[left_over] = 1;
    } else {
      if (used.size() < 2) break;  // one hide holds everything that fits
      if (streak >= kGiveUp * static_cast<long>(used.size())) break;  // no move found for long: done
      // Multi-hide: move one unit out of a little-filled hide into a fuller one; the least-filled
      // hide first, the next one after every kPerTarget failures in a row. A hide that loses its
      // last unit is closed.
      std::vector<int> order = used;
      std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return placed_area(best, a) / pieces_.slots[a].container->usable_area_mm2() <
               placed_area(best, b) / pieces_.slots[b].container->usable_area_mm2();
      });
      const int target = order[static_cast<size_t>(streak / kPerTarget) % order.size()];
      std::vector<int> units;
      for (size_t i = 0; i < best.slot_of.size(); ++i)
        if (best.slot_of[i] == target && std::find(units.begin(), units.end(), pieces_.unit_of[i]) == units.end())
          units.push_back(pieces_.unit_of[i]);
      std::stable_sort(units.begin(), units.end(), [&](int a, int b) { return pieces_.unit_area_mm2[a] > pieces_.unit_area_mm2[b]; });
      const int unit = units[static_cast<size_t>(streak) % units.size()];
      for (int p : pieces_.units[unit]) trial.slot_of[p] = -1;
      std::vector<int> destinations;
      for (int slot : used)
        if (slot != target && placed_area(best, slot) / pieces_.slots[slot].container->usable_area_mm2() >=
                                  placed_area(best, target) / pieces_.slots[target].container->usable_area_mm2())
          destinations.push_back(slot);
      std::stable_sort(destinations.begin(), destinations.end(),
                       [&](int a, int b) { return free_area(trial, a) > free_area(trial, b); });
      success = insert_anywhere(trial, unit, destinations, seed);
      streak = success ? 0 : streak + 1;
    }
    if (deadline_.passed()) break;  // a round cut short is not deterministic: drop it
    if (success) {
      best = std::move(trial);
      if (left_over < 0 && used_slots(best).size() < used.size()) std::fill(tried.begin(), tried.end(), 0);
      if (options_.on_improvement) options_.on_improvement(layout(best, false));
    }
  }
  return layout(best, true);
}

}  // namespace

Layout nest_hides_search(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options) {
  return HideSearch(instance, pieces, options).run();
}

}  // namespace lastcut::nest_detail
