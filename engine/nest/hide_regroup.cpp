// Units regrouped onto fewer hides with a per-hide packing oracle; see hide_regroup.hpp.
#include "engine/nest/hide_regroup.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "engine/nest/known_failures.hpp"

namespace lastcut::nest_detail {
namespace {

constexpr int kSwapCandidates = 40;  // swaps tried for one left-over unit before a kick
// No hide is asked to hold more than this share of its usable area: the oracle would spend its whole
// budget failing (Test6's ten hides hold its pieces at 56-69 % each).
constexpr double kPackFill = 0.78;
constexpr int kLongerQuestion = 4;  // a failing hide's own question is asked once more, this many times as long

struct Packing {
  bool complete = false;
  int effort = 1;                                      // the question's budget was effort x the base one
  std::vector<int> left_over;                          // units (of the parent) not placed
  std::vector<std::pair<int, PieceState>> placed;      // parent piece, its state on the hide
};

class Regroup {
 public:
  Regroup(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options,
          const std::vector<int>& target_slots, const Deadline& deadline, const RegroupBudget& budget, std::uint64_t seed,
          const HidePackingOracle& oracle)
      : instance_(instance), pieces_(pieces), options_(options), slots_(target_slots), deadline_(deadline),
        budget_(budget), random_(seed), seed_(seed), oracle_(oracle) {}

  std::optional<HidePlacement> run(const std::vector<int>& units);

 private:
  double area(int unit) const { return pieces_.unit_area_mm2[static_cast<size_t>(unit)]; }
  double usable(size_t target) const { return pieces_.slots[static_cast<size_t>(slots_[target])].container->usable_area_mm2(); }
  double load(size_t target) const {
    double sum = 0;
    for (int u : on_[target]) sum += area(u);
    return sum;
  }
  double left_over_area(const Packing& packing) const {
    double sum = 0;
    for (int u : packing.left_over) sum += area(u);
    return sum;
  }
  bool out_of_budget() const { return deadline_.passed() || calls_ >= budget_.most_oracle_calls; }
  // Whether target hide `target` holds `units` (the hide search on that hide alone), cached.
  const Packing& pack(size_t target, std::vector<int> units, int effort = 1);
  bool try_move(size_t from, int unit);
  bool try_swap(size_t from, int unit);

  const NestInstance& instance_;
  const HidePieces& pieces_;
  const NestOptions& options_;
  const std::vector<int>& slots_;
  const Deadline& deadline_;
  const RegroupBudget budget_;
  Random random_;
  std::uint64_t seed_;
  const HidePackingOracle& oracle_;  // one hide's packing: the hide search on it alone
  std::vector<std::vector<int>> on_;  // per target hide: its units
  std::map<std::pair<size_t, std::vector<int>>, Packing> cache_;
  KnownFailures failures_;  // per target hide, the unit sets the oracle could not pack there
  long calls_ = 0;
};

const Packing& Regroup::pack(size_t target, std::vector<int> units, int effort) {
  std::sort(units.begin(), units.end());
  auto key = std::make_pair(target, units);
  if (auto known = cache_.find(key); known != cache_.end()) {
    if (known->second.complete || known->second.effort >= effort) return known->second;
    failures_.forget(target, units);
    cache_.erase(known);  // asked again, longer
  }
  if (units.empty()) return cache_.emplace(std::move(key), Packing{.complete = true}).first->second;
  // A hide that could not hold some of these units (asked at least as long) will not hold them all: the
  // oracle is not asked. On Test6 that spares 3-17 of a regrouping's 24-140 questions, each a failing
  // search to the end of its budget; of 19 such questions asked anyway for a check, none was packed.
  if (const std::vector<int>* failed = failures_.failed_subset(target, units, effort)) {
    Packing surely_not{.complete = false, .effort = effort, .left_over = cache_.at({target, *failed}).left_over, .placed = {}};
    return cache_.emplace(std::move(key), std::move(surely_not)).first->second;
  }
  ++calls_;
  const int slot = slots_[target];
  // The hide alone, with the items of these units (a unit's pieces stay one unit: same pair group).
  NestInstance one = instance_;
  one.bins = {instance_.bins[static_cast<size_t>(pieces_.slots[static_cast<size_t>(slot)].bin_index)]};
  one.bins[0].stock = 1;
  std::map<int, std::vector<int>> pieces_of_item;  // parent item -> parent pieces, in piece order
  for (int u : units)
    for (int p : pieces_.units[static_cast<size_t>(u)]) pieces_of_item[pieces_.item_of[static_cast<size_t>(p)]].push_back(p);
  one.items.clear();
  std::vector<int> parent_piece;  // per piece of `one`, as prepare_hide_pieces numbers them
  for (auto& [item, list] : pieces_of_item) {
    std::sort(list.begin(), list.end());
    NestItem copy = instance_.items[static_cast<size_t>(item)];
    copy.demand = static_cast<int>(list.size());
    one.items.push_back(std::move(copy));
    parent_piece.insert(parent_piece.end(), list.begin(), list.end());
  }
  NestOptions alone = options_;
  alone.on_improvement = nullptr;
  alone.seed = stream_seed(seed_, static_cast<std::uint64_t>(calls_), 23);
  if (options_.iteration_limit) {
    alone.iteration_limit = budget_.oracle_rounds * effort;
    alone.time_limit_s = deadline_.seconds_left();
  } else {
    alone.time_limit_s = std::min(budget_.oracle_s * effort, deadline_.seconds_left());
  }
  Packing packing;
  packing.effort = effort;
  const HidePieces one_pieces = prepare_hide_pieces(one, alone);
  if (one_pieces.unplaced.empty() && one_pieces.item_of.size() == parent_piece.size()) {
    const HidePlacement found = oracle_(one, one_pieces, alone);
    packing.complete = true;
    for (size_t p = 0; p < parent_piece.size(); ++p) {
      const int parent = parent_piece[p];
      if (found.slot_of[p] < 0) {
        packing.complete = false;
        const int unit = pieces_.unit_of[static_cast<size_t>(parent)];
        if (std::find(packing.left_over.begin(), packing.left_over.end(), unit) == packing.left_over.end())
          packing.left_over.push_back(unit);
      } else {
        packing.placed.emplace_back(parent, found.state[p]);
      }
    }
  } else {
    packing.left_over = units;  // some piece has no pose on this hide at all
  }
  if (!packing.complete) failures_.add(target, units, effort);
  return cache_.emplace(std::move(key), std::move(packing)).first->second;
}

bool Regroup::try_move(size_t from, int unit) {
  std::vector<size_t> others;
  for (size_t t = 0; t < slots_.size(); ++t)
    if (t != from) others.push_back(t);
  std::stable_sort(others.begin(), others.end(), [&](size_t a, size_t b) { return load(a) / usable(a) < load(b) / usable(b); });
  for (size_t to : others) {
    if (load(to) + area(unit) > kPackFill * usable(to) || out_of_budget()) continue;
    std::vector<int> with = on_[to];
    with.push_back(unit);
    if (!pack(to, with).complete) continue;
    on_[to] = std::move(with);
    on_[from].erase(std::find(on_[from].begin(), on_[from].end(), unit));
    return true;
  }
  return false;
}

bool Regroup::try_swap(size_t from, int unit) {
  std::vector<std::pair<size_t, int>> candidates;  // (hide, its smaller unit)
  for (size_t to = 0; to < slots_.size(); ++to)
    if (to != from)
      for (int v : on_[to])
        if (area(v) < area(unit) && load(to) - area(v) + area(unit) <= kPackFill * usable(to)) candidates.emplace_back(to, v);
  for (size_t k = candidates.size(); k > 1; --k) std::swap(candidates[k - 1], candidates[static_cast<size_t>(random_.below(static_cast<int>(k)))]);
  if (candidates.size() > kSwapCandidates) candidates.resize(kSwapCandidates);
  for (const auto& [to, v] : candidates) {
    if (out_of_budget()) return false;
    std::vector<int> there = on_[to];
    *std::find(there.begin(), there.end(), v) = unit;
    if (!pack(to, there).complete) continue;
    std::vector<int> here = on_[from];
    *std::find(here.begin(), here.end(), unit) = v;
    if (left_over_area(pack(from, here)) >= area(unit)) continue;
    on_[to] = std::move(there);
    on_[from] = std::move(here);
    return true;
  }
  return false;
}

std::optional<HidePlacement> Regroup::run(const std::vector<int>& units) {
  // Worst fit by fill, largest unit first.
  on_.assign(slots_.size(), {});
  failures_ = KnownFailures(slots_.size());
  std::vector<int> order = units;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return area(a) > area(b); });
  for (int u : order) {
    size_t best = 0;
    for (size_t t = 1; t < slots_.size(); ++t)
      if ((load(t) + area(u)) / usable(t) < (load(best) + area(u)) / usable(best)) best = t;
    on_[best].push_back(u);
  }
  while (!out_of_budget()) {
    std::vector<size_t> failing;
    for (size_t t = 0; t < slots_.size() && !out_of_budget(); ++t)
      if (!pack(t, on_[t]).complete) failing.push_back(t);
    if (out_of_budget()) break;
    if (failing.empty()) {
      HidePlacement result{std::vector<int>(pieces_.item_of.size(), -1), std::vector<PieceState>(pieces_.item_of.size())};
      for (size_t t = 0; t < slots_.size(); ++t)
        for (const auto& [piece, state] : pack(t, on_[t]).placed) {
          result.slot_of[static_cast<size_t>(piece)] = slots_[t];
          result.state[static_cast<size_t>(piece)] = state;
        }
      return result;
    }
    const size_t from = failing[static_cast<size_t>(random_.below(static_cast<int>(failing.size())))];
    // A short question may miss a packing that exists: the hide is asked again, kLongerQuestion times as long.
    if (pack(from, on_[from]).effort < kLongerQuestion && pack(from, on_[from], kLongerQuestion).complete) continue;
    const std::vector<int> left = pack(from, on_[from]).left_over;
    const int unit = left[static_cast<size_t>(random_.below(static_cast<int>(left.size())))];
    if (try_move(from, unit) || try_swap(from, unit)) continue;
    // A kick: a random unit of that hide onto a random other hide.
    if (slots_.size() < 2) break;
    const int kicked = on_[from][static_cast<size_t>(random_.below(static_cast<int>(on_[from].size())))];
    size_t to = static_cast<size_t>(random_.below(static_cast<int>(slots_.size()) - 1));
    if (to >= from) ++to;
    on_[from].erase(std::find(on_[from].begin(), on_[from].end(), kicked));
    on_[to].push_back(kicked);
  }
  return std::nullopt;
}

}  // namespace

std::optional<HidePlacement> regroup_onto(const NestInstance& instance, const HidePieces& pieces,
                                          const NestOptions& options, const std::vector<int>& placed_slot_of,
                                          const std::vector<int>& target_slots, const Deadline& deadline,
                                          const RegroupBudget& budget, std::uint64_t seed, const HidePackingOracle& oracle) {
  if (target_slots.empty()) return std::nullopt;
  std::vector<int> units;
  for (size_t u = 0; u < pieces.units.size(); ++u)
    if (placed_slot_of[static_cast<size_t>(pieces.units[u].front())] >= 0) units.push_back(static_cast<int>(u));
  return Regroup(instance, pieces, options, target_slots, deadline, budget, seed, oracle).run(units);
}

}  // namespace lastcut::nest_detail
