#include "engine/nest/hide_eject.hpp"

#include <algorithm>

#include "engine/nest/parallel_separation.hpp"

namespace lastcut::nest_detail {
namespace {

constexpr int kPlaceSamples = 240;
constexpr int kSweepWorkers = 2;


class Chain {
 public:
  Chain(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options, const Deadline& deadline,
        std::vector<int>& slot_of, std::vector<PieceState>& state, const EjectBudget& budget)
      : instance_(instance), pieces_(pieces), options_(options), deadline_(deadline), slot_of_(slot_of), state_(state),
        budget_(budget) {}

  EjectResult run(int target, const std::vector<int>& destinations, std::uint64_t seed);

 private:
  double free_area(int slot) const { return free_area_mm2(pieces_, slot_of_, slot); }
  std::vector<int> units_on(int slot) const {
    std::vector<int> units;
    for (size_t i = 0; i < slot_of_.size(); ++i)
      if (slot_of_[i] == slot && std::find(units.begin(), units.end(), pieces_.unit_of[i]) == units.end())
        units.push_back(pieces_.unit_of[i]);
    return units;
  }
  void take_off(int unit) {
    for (int p : pieces_.units[unit]) slot_of_[p] = -1;
  }
  Separator::Objective near_first(int first, int slot) const { return near_piece(pieces_, first, slot, state_[first]); }
  // The chain stopped with `pool` left over: those units back onto the (emptied) target at free spots.
  EjectResult settle_back(int target, std::vector<int> pool, std::uint64_t seed);
  // Every piece of `unit` at a free sampled spot of `slot`, near each other; false when not.
  bool place_free(int slot, int unit, std::uint64_t seed);
  // Puts `units` onto `slot` and returns the units that had to leave it (off every hide now).
  std::vector<int> insert(int slot, const std::vector<int>& units, std::uint64_t seed);
  // The units that must leave so no overlap is left among the pieces `local` in `final` on `slot`:
  // the most overlap per mm^2 first, the units being inserted (`keep`) only when nothing else overlaps.
  std::vector<int> choose_ejected(int slot, const std::vector<int>& local, const std::vector<PieceState>& final,
                                  const std::vector<int>& keep, std::uint64_t seed) const;
  // Pair groups on `slot` whose pieces drifted apart: the strays re-placed near their first piece,
  // the groups that stay apart taken off and returned.
  std::vector<int> mend_pairs(int slot, std::uint64_t seed);

  const NestInstance& instance_;
  const HidePieces& pieces_;
  const NestOptions& options_;
  const Deadline& deadline_;
  std::vector<int>& slot_of_;
  std::vector<PieceState>& state_;
  const EjectBudget& budget_;
  std::vector<int> moved_;  // the units this chain has put somewhere: ejected again only as a last resort
};

EjectResult Chain::run(int target, const std::vector<int>& destinations, std::uint64_t seed) {
  std::vector<int> pool = units_on(target);
  if (pool.empty()) return EjectResult::Failed;
  double pool_area = 0, room = 0;
  for (int u : pool) take_off(u), pool_area += pieces_.unit_area_mm2[u];
  for (int d : destinations) room += free_area(d);
  if (room < pool_area) return EjectResult::Failed;  // the area alone rules it out
  // Per unit: the target and the hides it was ejected from (never tried again in this chain).
  std::vector<std::vector<int>> barred(pieces_.units.size(), std::vector<int>{target});
  const size_t max_steps = pool.size() + static_cast<size_t>(budget_.max_ejections);
  for (size_t step = 0; !pool.empty(); ++step) {
    if (step >= max_steps || deadline_.passed()) return settle_back(target, pool, seed);
    // The largest unit first: small ones find gaps later.
    auto largest = std::max_element(pool.begin(), pool.end(), [&](int a, int b) {
      return pieces_.unit_area_mm2[a] < pieces_.unit_area_mm2[b];
    });
    const int unit = *largest;
    pool.erase(largest);
    std::vector<int> candidates;
    for (int d : destinations) {
      bool poses = std::find(barred[unit].begin(), barred[unit].end(), d) == barred[unit].end();
      for (int p : pieces_.units[unit]) poses = poses && pieces_.fits_frame(p, d);
      if (poses) candidates.push_back(d);
    }
    std::stable_sort(candidates.begin(), candidates.end(), [&](int a, int b) { return free_area(a) > free_area(b); });
    // A free sampled spot on any of them first (cheap, no ejection).
    const std::vector<int> slot_of0 = slot_of_;
    const std::vector<PieceState> state0 = state_;
    bool free_spot = false;
    for (size_t c = 0; c < candidates.size() && !free_spot; ++c) {
      if (free_area(candidates[c]) < pieces_.unit_area_mm2[unit]) break;
      free_spot = place_free(candidates[c], unit, stream_seed(seed, step, 100 + c));
      if (!free_spot) slot_of_ = slot_of0, state_ = state0;
    }
    if (free_spot) continue;
    if (candidates.size() > static_cast<size_t>(budget_.destinations)) candidates.resize(budget_.destinations);
    // Each candidate hide on a copy; the one that ejects the least area (less than eject_ratio x the
    // unit's own, so the chain tends to smaller pieces) is kept, one that ejects nothing at once.
    std::vector<int> best_slot_of;
    std::vector<PieceState> best_state;
    std::vector<int> best_ejected;
    double best_area = budget_.eject_ratio * pieces_.unit_area_mm2[unit];
    int best_slot = -1;
    for (int d : candidates) {
      slot_of_ = slot_of0, state_ = state0;
      const std::vector<int> ejected = insert(d, {unit}, stream_seed(seed, step, static_cast<std::uint64_t>(d)));
      double area = 0;
      for (int e : ejected) area += e == unit ? 1e300 : pieces_.unit_area_mm2[e];
      if (area < best_area) {
        best_area = area, best_slot = d, best_ejected = ejected;
        best_slot_of = slot_of_, best_state = state_;
      }
      if (area == 0 || deadline_.passed()) break;
    }
    if (best_slot < 0) {
      pool.push_back(unit);
      return settle_back(target, pool, seed);
    }
    slot_of_ = std::move(best_slot_of), state_ = std::move(best_state);
    for (int e : best_ejected) barred[e].push_back(best_slot), pool.push_back(e);
    moved_.push_back(unit);
  }
  return EjectResult::Emptied;
}

EjectResult Chain::settle_back(int target, std::vector<int> pool, std::uint64_t seed) {
  if (deadline_.passed()) return EjectResult::Failed;
  std::stable_sort(pool.begin(), pool.end(), [&](int a, int b) { return pieces_.unit_area_mm2[a] > pieces_.unit_area_mm2[b]; });
  for (size_t k = 0; k < pool.size(); ++k)
    if (!place_free(target, pool[k], stream_seed(seed, k, 31))) return EjectResult::Failed;
  return EjectResult::Rearranged;
}

bool Chain::place_free(int slot, int unit, std::uint64_t seed) {
  return place_unit_free(pieces_, instance_, unit, slot, slot_of_, state_, kPlaceSamples, seed);
}

std::vector<int> Chain::insert(int slot, const std::vector<int>& units, std::uint64_t seed) {
  // A free sampled spot first (cheap); pair members as near their first piece as the samples allow.
  std::vector<int> rest;
  for (size_t k = 0; k < units.size(); ++k) {
    const std::vector<int>& members = pieces_.units[units[k]];
    for (size_t m = 0; m < members.size(); ++m) {
      Separator::Objective objective = [](const Box& b) { return b.x1 + 1e-3 * b.y0; };
      if (m > 0 && slot_of_[members[0]] == slot) objective = near_first(members[0], slot);
      if (!place_on_slot(pieces_, members[m], slot, slot_of_, state_, objective, kPlaceSamples, stream_seed(seed, k, m)))
        rest.push_back(members[m]);
    }
  }
  std::vector<int> ejected;
  if (!rest.empty()) {
    // The rest dropped in at a random pose and spot (a pair member onto its first piece), overlapping,
    // and the whole hide separated.
    Random random(stream_seed(seed, 0, 9));
    std::vector<int> local;
    for (size_t i = 0; i < slot_of_.size(); ++i)
      if (slot_of_[i] == slot) local.push_back(static_cast<int>(i));
    std::vector<const PreparedItem*> prepared;
    std::vector<PieceState> start;
    for (int p : local) prepared.push_back(&pieces_.prepared(p, slot)), start.push_back(state_[p]);
    for (int p : rest) {
      const PreparedItem& item = pieces_.prepared(p, slot);
      PieceState st;
      st.orientation = random.below(static_cast<int>(item.orientations.size()));
      const Box range = pieces_.slots[slot].container->offset_range(item.orientations[st.orientation]);
      st.offset = {random.uniform(range.x0, range.x1), random.uniform(range.y0, range.y1)};
      const int first = pieces_.units[pieces_.unit_of[p]].front();
      if (first != p) {
        const auto at = std::find(local.begin(), local.end(), first);
        if (at != local.end()) st.offset = start[static_cast<size_t>(at - local.begin())].offset;
      }
      local.push_back(p);
      prepared.push_back(&item);
      start.push_back(st);
    }
    ParallelSeparation separation(prepared, *pieces_.slots[slot].container, seed,
                                  std::min(kSweepWorkers, options_.sweep_workers), options_.threads, options_.run_parallel);
    separation.set_state(start);
    const bool feasible = separation.separate(budget_.strikes, budget_.stale, deadline_);
    const std::vector<PieceState> final = separation.state();
    std::vector<int> keep = moved_;
    keep.insert(keep.end(), units.begin(), units.end());
    if (!feasible) ejected = choose_ejected(slot, local, final, keep, seed);
    for (size_t k = 0; k < local.size(); ++k) slot_of_[local[k]] = slot, state_[local[k]] = final[k];
    for (int u : ejected) take_off(u);
  }
  for (int u : mend_pairs(slot, seed)) ejected.push_back(u);
  return ejected;
}

std::vector<int> Chain::choose_ejected(int slot, const std::vector<int>& local, const std::vector<PieceState>& final,
                                       const std::vector<int>& keep, std::uint64_t seed) const {
  std::vector<const PreparedItem*> prepared;
  for (int p : local) prepared.push_back(&pieces_.prepared(p, slot));
  Separator probe(prepared, *pieces_.slots[slot].container, seed);
  probe.set_state(final);
  const size_t n = local.size();
  std::vector<char> active(n, 1);
  std::vector<int> ejected;
  for (;;) {
    std::vector<double> unit_loss(pieces_.units.size(), 0);
    bool any = false;
    for (size_t a = 0; a < n; ++a) {
      if (!active[a]) continue;
      double loss = probe.exterior_loss(static_cast<int>(a));
      for (size_t b = 0; b < n; ++b)
        if (b != a && active[b]) loss += probe.pair_loss(static_cast<int>(a), static_cast<int>(b));
      unit_loss[pieces_.unit_of[local[a]]] += loss;
      any = any || loss > 0;
    }
    if (!any) return ejected;
    int worst = -1;
    auto score = [&](int u) {
      const bool kept = std::find(keep.begin(), keep.end(), u) != keep.end();
      return unit_loss[u] / pieces_.unit_area_mm2[u] - (kept ? 1e300 : 0);
    };
    for (int u = 0; u < static_cast<int>(unit_loss.size()); ++u)
      if (unit_loss[u] > 0 && (worst < 0 || score(u) > score(worst))) worst = u;
    ejected.push_back(worst);
    for (size_t a = 0; a < n; ++a)
      if (pieces_.unit_of[local[a]] == worst) active[a] = 0;
  }
}

std::vector<int> Chain::mend_pairs(int slot, std::uint64_t seed) {
  std::vector<int> apart;
  for (int u : units_on(slot)) {
    if (unit_near(pieces_, instance_, u, slot, state_)) continue;
    const std::vector<int>& group = pieces_.units[u];
    for (size_t m = 1; m < group.size(); ++m) {
      const PieceState old_state = state_[group[m]];
      slot_of_[group[m]] = -1;
      if (!place_on_slot(pieces_, group[m], slot, slot_of_, state_, near_first(group[0], slot), 2 * kPlaceSamples,
                         stream_seed(seed, m, 3)))
        slot_of_[group[m]] = slot, state_[group[m]] = old_state;
    }
    if (!unit_near(pieces_, instance_, u, slot, state_)) take_off(u), apart.push_back(u);
  }
  return apart;
}

}  // namespace

EjectTurn eject_turn(const NestInstance& instance, const HidePieces& pieces, const std::vector<int>& order, long turn,
                     bool replace_only) {
  EjectTurn result;
  if (order.empty()) return result;
  const size_t k = static_cast<size_t>(turn), n = order.size();
  const int target = order[k % n];
  for (int slot : order)
    if (slot != target) result.destinations.push_back(slot);
  if (replace_only || (k / n) % 2 == 1) {
    auto usable = [&](int slot) { return pieces.slots[slot].container->usable_area_mm2(); };
    auto cost = [&](int slot) { return instance.bins[pieces.slots[slot].bin_index].cost; };
    std::vector<int> smaller;  // in the opening order: largest first among equal prices per area
    for (int slot = 0; slot < static_cast<int>(pieces.slots.size()); ++slot)
      if (std::find(order.begin(), order.end(), slot) == order.end() && usable(slot) < usable(target) &&
          cost(slot) <= cost(target))
        smaller.push_back(slot);
    if (smaller.empty()) return result;
    result.destinations.push_back(smaller[(k / (2 * n)) % smaller.size()]);
  }
  result.target = target;
  return result;
}

EjectResult eject_hide(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options,
                const Deadline& deadline, std::vector<int>& slot_of, std::vector<PieceState>& state, int target,
                const std::vector<int>& destinations, std::uint64_t seed, const EjectBudget& budget) {
  return Chain(instance, pieces, options, deadline, slot_of, state, budget).run(target, destinations, seed);
}

}  // namespace lastcut::nest_detail
