#include "engine/nest/hide_search.hpp"

#include <algorithm>
#include <numeric>
#include <optional>

#include "engine/nest/hide_eject.hpp"
#include "engine/nest/hide_greedy.hpp"
#include "engine/nest/hide_merge.hpp"
#include "engine/nest/hide_regroup.hpp"
#include "engine/nest/hide_repack.hpp"
#include "engine/nest/nest_random.hpp"
#include "engine/nest/parallel_separation.hpp"

namespace lastcut::nest_detail {
namespace {

// Separation budget of one insertion at effort level 0 (strikes of `kStale` sweeps without a 2 %
// improvement): a small budget tried often beat 3 x 40 sweeps on Test1, Test5 and Test6 at 10 s
// (docs/benchmarks-nest.md). Each level of effort adds kStale sweeps per strike and one destination.
constexpr int kStrikes = 2, kStale = 15;
constexpr int kMaxLevel = 2;  // levels of effort before a restart
constexpr int kChainDestinations = 3, kMaxEjections = 8;  // one ejection chain: hides per unit, units ejected
constexpr int kPlaceSamples = 240;
constexpr int kHideSweepWorkers = 2;
constexpr int kDestinations = 2;  // hides an inserted unit tries at level 0, most free area first
constexpr long kShrinkTries = 40;  // failed shrinks in a row that end the search at the area bound
constexpr long kPerTarget = 4;    // failed attempts on one hide before the next one is tried
constexpr long kChainPeriod = 2;  // every other attempt is an ejection chain (3 and 1 measured worse)
constexpr long kMergePeriod = 3;  // every third chain merges two hides into an unused one (hide_merge)
constexpr double kMergeFill = 0.74;  // merges tried up to this fill of the hides left (Test1: 72 % reached)
constexpr double kRegroupFill = 0.74;  // regroupings tried up to this fill of the fewer hides
constexpr double kRegroupMin_s = 10;   // time of one regrouping, unless less is left
constexpr long kRegroupUnitsPerHide = 10;  // regroupings only where the hides hold this few units on average
constexpr long kRegroupAfterRounds = 5;  // rounds without a hide fewer before the regrouping is tried


// How hard one insertion tries; grows while no attempt succeeds, back to 0 after a success.
struct Effort {
  int level = 0;
  int strikes() const { return kStrikes; }
  int stale() const { return kStale * (1 + level); }
  int destinations() const { return kDestinations + level; }
};

class HideSearch {
 public:
  HideSearch(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options)
      : instance_(instance), pieces_(pieces), options_(options), deadline_(options.time_limit_s) {}

  using State = HidePlacement;
  // The best placement of all trajectories, and as a layout.
  State best_placement();
  Layout run() { return layout(best_placement(), true); }

 private:
  double placed_area(const State& s, int slot) const { return placed_area_mm2(pieces_, s.slot_of, slot); }
  double fill(const State& s, int slot) const { return placed_area(s, slot) / pieces_.slots[slot].container->usable_area_mm2(); }
  double free_area(const State& s, int slot) const { return free_area_mm2(pieces_, s.slot_of, slot); }
  std::vector<int> used_slots(const State& s) const {
    std::vector<int> used;
    for (int slot : s.slot_of)
      if (slot >= 0 && std::find(used.begin(), used.end(), slot) == used.end()) used.push_back(slot);
    std::sort(used.begin(), used.end());
    return used;
  }
  std::vector<int> units_on(const State& s, int slot) const {
    std::vector<int> units;
    for (size_t i = 0; i < s.slot_of.size(); ++i)
      if (s.slot_of[i] == slot && std::find(units.begin(), units.end(), pieces_.unit_of[i]) == units.end())
        units.push_back(pieces_.unit_of[i]);
    std::stable_sort(units.begin(), units.end(), [&](int a, int b) { return pieces_.unit_area_mm2[a] > pieces_.unit_area_mm2[b]; });
    return units;
  }
  size_t area_bound(const State& s) const { return hide_area_bound(pieces_, s.slot_of); }
  // The used hides, the one to empty first first: least filled, then the smallest.
  std::vector<int> targets(const State& s) const;
  bool insert_unit(State& s, int unit, int slot, std::uint64_t seed, const Effort& effort) const;
  bool insert_anywhere(State& s, int unit, const std::vector<int>& destinations, std::uint64_t seed, const Effort& effort) const;
  // Attempt k since the last success, on a copy of the best state: one unit of a little-filled hide
  // onto a hide at least as full (move), or, from level 1 on every other attempt, exchanged for a
  // smaller unit of such a hide (swap). Both make the little-filled hide emptier.
  bool move_or_swap(State& s, long k, std::uint64_t seed, const Effort& effort) const;
  bool swap(State& s, int target, int unit, long k, std::uint64_t seed, const Effort& effort) const;
  // The target hide and a fuller one packed again by the greedy, the fuller one first, the units of
  // both in a perturbed largest-first order; kept when the concentration grows.
  bool repack(State& s, int target, long k, std::uint64_t seed) const;
  // Every unit of a used hide onto an unused smaller one that has room for their area (the
  // `index`-th such pair, the lowest resulting fill first; no dearer hide): the same pieces on less leather.
  bool shrink(State& s, long index, std::uint64_t seed, const Effort& effort) const;
  // The `index`-th ejection chain (engine/nest/hide_eject): the used hides to empty in turn, least
  // filled first; every other turn an unused smaller hide, no dearer, joins the destinations (a big
  // hide replaced by a smaller one). At the area bound only the replacing turns are tried.
  bool chain(State& s, long index, std::uint64_t seed, const Effort& effort) const;
  // `s` (every unit placed) regrouped onto the first hides of the opening order, one fewer than it
  // uses (engine/nest/hide_regroup), when they could hold its pieces at kRegroupFill by area with at
  // most kRegroupUnitsPerHide units a hide on average; within 90 % of the time left (at least
  // kRegroupMin_s, unless less is left).
  std::optional<State> regroup(const State& s, long turn) const;
  // More placed area, then fewer hides, then more concentrated.
  bool better(const State& a, const State& b) const;
  // A new trajectory: the greedy in a perturbed order.
  State restart(long restarts) const;
  bool any_left_over(const State& s) const;  // a piece on no hide
  Layout layout(const State& s, bool with_reasons) const {
    return finish_hides(instance_, pieces_, s.slot_of, s.state, with_reasons, options_.seed);
  }

  const NestInstance& instance_;
  const HidePieces& pieces_;
  const NestOptions& options_;
  Deadline deadline_;
};

std::vector<int> HideSearch::targets(const State& s) const {
  std::vector<int> order = used_slots(s);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const double fa = fill(s, a), fb = fill(s, b);
    if (std::abs(fa - fb) > 1e-9) return fa < fb;
    return pieces_.slots[a].container->usable_area_mm2() < pieces_.slots[b].container->usable_area_mm2();
  });
  return order;
}

bool HideSearch::insert_unit(State& s, int unit, int slot, std::uint64_t seed, const Effort& effort) const {
  const std::vector<int>& members = pieces_.units[unit];
  for (int p : members)
    if (!pieces_.fits_frame(p, slot)) return false;
  // A free sampled spot first (cheap); pair members as near the first one as the samples allow.
  std::vector<int> rest;
  for (size_t m = 0; m < members.size(); ++m) {
    const int p = members[m];
    Separator::Objective objective = [](const Box& b) { return b.x1 + 1e-3 * b.y0; };
    if (m > 0 && s.slot_of[members[0]] == slot) objective = near_piece(pieces_, members[0], slot, s.state[members[0]]);
    if (!place_on_slot(pieces_, p, slot, s.slot_of, s.state, objective, kPlaceSamples, stream_seed(seed, m, 1)))
      rest.push_back(p);
  }
  if (!rest.empty()) {
    // Drop the rest in and separate the hide: at the hide's centre at first, at a random pose and
    // spot once the plain attempts failed (another start, another outcome of the separation).
    Random random(stream_seed(seed, 0, 9));
    std::vector<int> local;
    for (size_t i = 0; i < s.slot_of.size(); ++i)
      if (s.slot_of[i] == slot) local.push_back(static_cast<int>(i));
    std::vector<const PreparedItem*> prepared;
    std::vector<PieceState> start;
    for (int p : local) prepared.push_back(&pieces_.prepared(p, slot)), start.push_back(s.state[p]);
    for (int p : rest) {
      const PreparedItem& item = pieces_.prepared(p, slot);
      PieceState st{0, pieces_.slots[slot].container->offset_range(item.orientations[0]).centre()};
      if (effort.level > 0) {
        st.orientation = random.below(static_cast<int>(item.orientations.size()));
        const Box range = pieces_.slots[slot].container->offset_range(item.orientations[st.orientation]);
        st.offset = {random.uniform(range.x0, range.x1), random.uniform(range.y0, range.y1)};
      }
      if (s.slot_of[members[0]] == slot) st.offset = s.state[members[0]].offset;  // next to its pair
      local.push_back(p);
      prepared.push_back(&item);
      start.push_back(st);
    }
    ParallelSeparation separation(prepared, *pieces_.slots[slot].container, seed, std::min(kHideSweepWorkers, options_.sweep_workers),
                                  options_.threads, options_.run_parallel);
    separation.set_state(start);
    if (!separation.separate(effort.strikes(), effort.stale(), deadline_)) return false;
    for (size_t k = 0; k < local.size(); ++k) s.slot_of[local[k]] = slot, s.state[local[k]] = separation.state()[k];
  }
  // Pairs on this hide must still be near each other: re-place a stray piece next to its first one.
  for (int u : units_on(s, slot)) {
    if (unit_near(pieces_, instance_, u, slot, s.state)) continue;
    const std::vector<int>& group = pieces_.units[u];
    for (size_t m = 1; m < group.size(); ++m) {
      const Separator::Objective near_first = near_piece(pieces_, group[0], slot, s.state[group[0]]);
      const int old_slot = s.slot_of[group[m]];
      const PieceState old_state = s.state[group[m]];
      s.slot_of[group[m]] = -1;
      if (!place_on_slot(pieces_, group[m], slot, s.slot_of, s.state, near_first, 2 * kPlaceSamples,
                         stream_seed(seed, m, 3)))
        s.slot_of[group[m]] = old_slot, s.state[group[m]] = old_state;
    }
    if (!unit_near(pieces_, instance_, u, slot, s.state)) return false;
  }
  return true;
}

bool HideSearch::insert_anywhere(State& s, int unit, const std::vector<int>& destinations, std::uint64_t seed,
                                 const Effort& effort) const {
  int tried = 0;
  for (int slot : destinations) {
    if (free_area(s, slot) < pieces_.unit_area_mm2[unit]) continue;
    State trial = s;
    if (insert_unit(trial, unit, slot, stream_seed(seed, static_cast<std::uint64_t>(slot), 5), effort)) {
      s = std::move(trial);
      return true;
    }
    if (++tried == effort.destinations() || deadline_.passed()) break;
  }
  return false;
}

bool HideSearch::move_or_swap(State& s, long k, std::uint64_t seed, const Effort& effort) const {
  const std::vector<int> order = targets(s);
  const int target = order[static_cast<size_t>(k / kPerTarget) % order.size()];
  const std::vector<int> units = units_on(s, target);
  const int unit = units[static_cast<size_t>(effort.level > 0 ? k / 3 : k) % units.size()];
  if (effort.level > 0 && k % 4 == 1) return swap(s, target, unit, k, seed, effort);
  if (effort.level > 0 && k % 4 == 2) return repack(s, target, k, seed);
  if (effort.level > 0 && k % 4 == 3) return shrink(s, k / 4, seed, effort);
  const double target_fill = fill(s, target);
  for (int p : pieces_.units[unit]) s.slot_of[p] = -1;
  std::vector<int> destinations;
  for (int slot : order)
    if (slot != target && fill(s, slot) >= target_fill) destinations.push_back(slot);
  std::stable_sort(destinations.begin(), destinations.end(), [&](int a, int b) { return free_area(s, a) > free_area(s, b); });
  return insert_anywhere(s, unit, destinations, seed, effort);
}

bool HideSearch::swap(State& s, int target, int unit, long k, std::uint64_t seed, const Effort& effort) const {
  // Partner: a hide at least as full holding a smaller unit whose place (plus its free area) the
  // larger one could take; the partners and their units in turn, largest smaller unit first.
  const double target_fill = fill(s, target), area = pieces_.unit_area_mm2[unit];
  std::vector<std::pair<int, int>> candidates;  // (hide, unit)
  for (int slot : targets(s)) {
    if (slot == target || fill(s, slot) < target_fill) continue;
    for (int v : units_on(s, slot))
      if (pieces_.unit_area_mm2[v] < area && free_area(s, slot) + pieces_.unit_area_mm2[v] >= area)
        candidates.emplace_back(slot, v);
  }
  if (candidates.empty()) return false;
  const auto [partner, other] = candidates[static_cast<size_t>(k / 3) % candidates.size()];
  for (int p : pieces_.units[unit]) s.slot_of[p] = -1;
  for (int p : pieces_.units[other]) s.slot_of[p] = -1;
  return insert_unit(s, unit, partner, stream_seed(seed, 1, 5), effort) &&
         insert_unit(s, other, target, stream_seed(seed, 2, 5), effort);
}

bool HideSearch::repack(State& s, int target, long k, std::uint64_t seed) const {
  const double before = concentration(pieces_, s.slot_of), target_fill = fill(s, target);
  std::vector<int> partners;
  for (int slot : targets(s))
    if (slot != target && fill(s, slot) >= target_fill) partners.push_back(slot);
  if (partners.empty()) return false;
  const int partner = partners[static_cast<size_t>(k / 3) % partners.size()];
  std::vector<int> units = units_on(s, partner);
  for (int u : units_on(s, target)) units.push_back(u);
  Random random(stream_seed(seed, 0, 13));
  units = perturbed_order(pieces_, units, random, false);
  if (!repack_hides(instance_, pieces_, s.slot_of, s.state, {partner, target}, units, seed)) return false;
  return concentration(pieces_, s.slot_of) > before * (1 + 1e-9);
}

bool HideSearch::shrink(State& s, long index, std::uint64_t seed, const Effort& effort) const {
  const std::vector<int> used = used_slots(s);
  auto usable = [&](int slot) { return pieces_.slots[slot].container->usable_area_mm2(); };
  auto cost = [&](int slot) { return instance_.bins[pieces_.slots[slot].bin_index].cost; };
  std::vector<std::pair<int, int>> candidates;  // (used hide, smaller unused hide)
  for (int from : used)
    for (int to = 0; to < static_cast<int>(pieces_.slots.size()); ++to)
      if (std::find(used.begin(), used.end(), to) == used.end() && usable(to) < usable(from) &&
          usable(to) >= placed_area(s, from) && cost(to) <= cost(from))
        candidates.emplace_back(from, to);
  if (candidates.empty()) return false;
  // The likeliest first: the lowest fill the pieces would have on the smaller hide.
  std::stable_sort(candidates.begin(), candidates.end(), [&](const auto& a, const auto& b) {
    return placed_area(s, a.first) / usable(a.second) < placed_area(s, b.first) / usable(b.second);
  });
  const auto [from, to] = candidates[static_cast<size_t>(index) % candidates.size()];
  const std::vector<int> units = units_on(s, from);
  for (int u : units)
    for (int p : pieces_.units[u]) s.slot_of[p] = -1;
  for (int u : units)
    if (!insert_unit(s, u, to, stream_seed(seed, static_cast<std::uint64_t>(u), 21), effort)) return false;
  return true;
}

bool HideSearch::chain(State& s, long index, std::uint64_t seed, const Effort& effort) const {
  const std::vector<int> order = targets(s);
  const EjectBudget budget{effort.strikes(), effort.stale(), kChainDestinations + effort.level, kMaxEjections};
  if (index % kMergePeriod == kMergePeriod - 1 && order.size() > area_bound(s))
    return merge_hides(instance_, pieces_, options_, deadline_, s.slot_of, s.state,
                       merge_turn(instance_, pieces_, s.slot_of, order, index / kMergePeriod, kMergeFill), seed, budget);
  const EjectTurn turn = eject_turn(instance_, pieces_, order, index - (index + 1) / kMergePeriod, order.size() <= area_bound(s));
  if (turn.target < 0) return false;
  const double before = concentration(pieces_, s.slot_of);
  switch (eject_hide(instance_, pieces_, options_, deadline_, s.slot_of, s.state, turn.target, turn.destinations, seed, budget)) {
    case EjectResult::Emptied: return true;
    case EjectResult::Rearranged: return concentration(pieces_, s.slot_of) > before * (1 + 1e-9);
    case EjectResult::Failed: return false;
  }
  return false;
}

bool HideSearch::better(const State& a, const State& b) const {
  double placed_a = 0, placed_b = 0;
  for (size_t i = 0; i < a.slot_of.size(); ++i) {
    const double area = pieces_.frames[0][pieces_.item_of[i]].area_mm2;
    placed_a += a.slot_of[i] >= 0 ? area : 0;
    placed_b += b.slot_of[i] >= 0 ? area : 0;
  }
  if (std::abs(placed_a - placed_b) > 1e-9 * std::max(1.0, placed_a)) return placed_a > placed_b;
  const std::vector<int> used_a = used_slots(a), used_b = used_slots(b);
  if (used_a.size() != used_b.size()) return used_a.size() < used_b.size();
  // Then less leather (a higher utilisation of the used hides).
  double area_a = 0, area_b = 0;
  for (int slot : used_a) area_a += pieces_.slots[slot].container->usable_area_mm2();
  for (int slot : used_b) area_b += pieces_.slots[slot].container->usable_area_mm2();
  if (std::abs(area_a - area_b) > 1e-9 * area_a) return area_a < area_b;
  return concentration(pieces_, a.slot_of) > concentration(pieces_, b.slot_of) * (1 + 1e-9);
}

std::optional<HideSearch::State> HideSearch::regroup(const State& s, long turn) const {
  const std::vector<int> used = used_slots(s);
  if (any_left_over(s) || used.size() < 2 || used.size() - 1 < area_bound(s)) return std::nullopt;
  std::vector<int> targets(used.size() - 1);
  std::iota(targets.begin(), targets.end(), 0);  // slots are in opening order: cheapest, then largest
  double placed = 0, usable = 0;
  for (int slot : used) placed += placed_area(s, slot);
  for (int slot : targets) usable += pieces_.slots[static_cast<size_t>(slot)].container->usable_area_mm2();
  if (placed > kRegroupFill * usable) return std::nullopt;
  // Many small units a hide: the moves do well there, and each per-hide search is long (shoe batches).
  const long units = std::count_if(pieces_.units.begin(), pieces_.units.end(),
                                   [&](const std::vector<int>& u) { return s.slot_of[static_cast<size_t>(u.front())] >= 0; });
  if (units > kRegroupUnitsPerHide * static_cast<long>(targets.size())) return std::nullopt;
  const Deadline slice(std::min(deadline_.seconds_left(), std::max(kRegroupMin_s, 0.9 * deadline_.seconds_left())));
  auto found = regroup_onto(instance_, pieces_, options_, s.slot_of, targets, slice, RegroupBudget{},
                            stream_seed(options_.seed, static_cast<std::uint64_t>(turn), 29), search_hide_placement);
  if (!found) return std::nullopt;
  return State{std::move(found->slot_of), std::move(found->state)};
}

bool HideSearch::any_left_over(const State& s) const {
  return std::any_of(s.slot_of.begin(), s.slot_of.end(), [](int slot) { return slot < 0; });
}

HideSearch::State HideSearch::restart(long restarts) const {
  // The greedy in a perturbed largest-first order (priorities first), as the iterated greedy does.
  Random random(stream_seed(options_.seed, static_cast<std::uint64_t>(restarts), 17));
  std::vector<int> units(pieces_.units.size());
  std::iota(units.begin(), units.end(), 0);
  const std::vector<int> order = perturbed_order(pieces_, units, random, true);
  const HideAssignment start = greedy_hides(instance_, pieces_, order, random.next());
  return {start.slot_of, start.state};
}

HideSearch::State HideSearch::best_placement() {
  const HideAssignment start = greedy_hides(instance_, pieces_, unit_order_by_value(pieces_), stream_seed(options_.seed, 0, 0));
  State best{start.slot_of, start.state};
  State current = best;  // the trajectory searched now; best = the best state of all trajectories
  if (options_.on_improvement) options_.on_improvement(layout(best, false));
  const int n_slots = static_cast<int>(pieces_.slots.size());
  long streak = 0, restarts = 0;  // multi-hide attempts since the last success; trajectories started
  size_t regroup_count = 0;       // hides of the best layout when last counted
  long rounds_at_count = 0;       // rounds since the best layout's hide count changed
  std::vector<char> tried(pieces_.units.size(), 0);
  const std::vector<int> by_value = unit_order_by_value(pieces_);
  // A new trajectory from a perturbed greedy start; the best of all is kept.
  const auto new_trajectory = [&] {
    current = restart(++restarts);
    streak = 0;
    std::fill(tried.begin(), tried.end(), 0);
    if (better(current, best)) {
      best = current;
      if (options_.on_improvement) options_.on_improvement(layout(best, false));
    }
  };
  for (long round = 1; !options_.iteration_limit || round <= *options_.iteration_limit; ++round) {
    if (deadline_.passed()) break;
    const std::uint64_t seed = stream_seed(options_.seed, static_cast<std::uint64_t>(round), 0);
    // Once the moves have kept the best layout's hide count for kRegroupAfterRounds rounds: that layout
    // regrouped onto one hide fewer (hide_regroup), once per hide count.
    if (const size_t count = used_slots(best).size(); count != regroup_count) {
      regroup_count = count;
      rounds_at_count = 0;
    }
    if (++rounds_at_count == kRegroupAfterRounds) {
      if (auto fewer = regroup(best, round)) {
        current = std::move(*fewer);
        streak = 0;
        std::fill(tried.begin(), tried.end(), 0);
        if (better(current, best)) {
          best = current;
          if (options_.on_improvement) options_.on_improvement(layout(best, false));
        }
        continue;
      }
      if (deadline_.passed()) break;
    }
    const std::vector<int> used = used_slots(current);
    State trial = current;
    bool success = false;
    // Knapsack: a unit left over, most valuable first.
    int left_over = -1;
    for (int u : by_value)
      if (!tried[u] && current.slot_of[pieces_.units[u].front()] < 0) {
        left_over = u;
        break;
      }
    if (left_over >= 0) {
      // The used hides, most free area first; failing those, the unused hides in opening order. Each
      // list gets its own tries: behind the used hides' limit an unused hide was never reached, and a
      // unit the greedy start left over stayed off for good (Test6, seed 6: 42 of 43 pieces placed).
      std::vector<int> destinations = used, unused;
      std::stable_sort(destinations.begin(), destinations.end(),
                       [&](int a, int b) { return free_area(current, a) > free_area(current, b); });
      for (int slot = 0; slot < n_slots; ++slot)
        if (std::find(used.begin(), used.end(), slot) == used.end()) unused.push_back(slot);
      success = insert_anywhere(trial, left_over, destinations, seed, Effort{}) ||
                insert_anywhere(trial, left_over, unused, seed, Effort{});
      if (!success) tried[left_over] = 1;
    } else {
      // Multi-hide: fewer hides, until the budget. When the used hides are as few as their area
      // allows (or one hide holds everything that fits) only smaller hides are left to try.
      if (used.size() < 2 || used.size() <= area_bound(current)) {
        if (streak >= kShrinkTries) {
          // Every piece placed on as few hides as their area allows: done. Pieces left over (the
          // knapsack form, one hide): a new trajectory from a perturbed greedy start, as the iterated
          // greedy does, rather than ending with budget left (it ended after 3-10 s of 30 and placed
          // less area than the iterated greedy on some hides: docs/benchmarks-nest.md).
          if (!any_left_over(current)) break;
          new_trajectory();
          continue;
        }
        success = streak % 2 ? chain(trial, streak / 2, seed, Effort{1}) : shrink(trial, streak / 2, seed, Effort{1});
        streak = success ? 0 : streak + 1;
      } else {
        const long cycles = streak / (kPerTarget * static_cast<long>(used.size()));
        // Stuck: a new trajectory from a perturbed greedy start. The search's outcome hangs on a few
        // lucky moves early on, so a trajectory that is behind the best gets one cycle, one as good
        // as the best every level of effort.
        if (cycles > (used.size() <= used_slots(best).size() ? kMaxLevel : 0)) {
          new_trajectory();
          continue;
        }
        const Effort effort{static_cast<int>(cycles)};
        success = streak % kChainPeriod == kChainPeriod - 1 ? chain(trial, streak / kChainPeriod, seed, effort)
                                                            : move_or_swap(trial, streak / kChainPeriod, seed, effort);
        streak = success ? 0 : streak + 1;
      }
    }
    if (deadline_.passed()) break;  // a round cut short is not deterministic: drop it
    if (success) {
      const size_t used_before = used.size();
      current = std::move(trial);
      if (left_over < 0 && used_slots(current).size() < used_before) std::fill(tried.begin(), tried.end(), 0);
      if (better(current, best)) {
        best = current;
        if (options_.on_improvement) options_.on_improvement(layout(best, false));
      }
    }
  }
  return best;
}

}  // namespace

Layout nest_hides_search(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options) {
  return HideSearch(instance, pieces, options).run();
}

HidePlacement search_hide_placement(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options) {
  return HideSearch(instance, pieces, options).best_placement();
}

}  // namespace lastcut::nest_detail
