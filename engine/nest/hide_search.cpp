// The hide search's main loop: start, rounds of scheduled moves, restarts, regrouping; see hide_search.hpp.
#include "engine/nest/hide_search.hpp"

#include <algorithm>
#include <numeric>

#include "engine/nest/hide_greedy.hpp"
#include "engine/nest/hide_moves.hpp"
#include "engine/nest/nest_random.hpp"

namespace lastcut::nest_detail {
namespace {

class HideSearch {
 public:
  HideSearch(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options)
      : instance_(instance), pieces_(pieces), options_(options), deadline_(options.time_limit_s),
        context_{instance, pieces, options, deadline_, tuning_} {}

  // The best placement of all trajectories, and as a layout.
  HidePlacement best_placement();
  Layout run() { return layout(HideSearchState(pieces_, best_placement()), true); }

 private:
  // A trajectory's start: the greedy in the order by value (the first), then in perturbed orders.
  HideSearchState start(long restarts) const;
  Layout layout(const HideSearchState& s, bool with_reasons) const {
    return finish_hides(instance_, pieces_, s.slot_of(), s.state(), with_reasons, options_.seed);
  }

  const NestInstance& instance_;
  const HidePieces& pieces_;
  const NestOptions& options_;
  const HideSearchTuning tuning_;
  const Deadline deadline_;
  const MoveContext context_;
};

HideSearchState HideSearch::start(long restarts) const {
  if (restarts == 0) {
    const HideAssignment first = greedy_hides(instance_, pieces_, unit_order_by_value(pieces_), stream_seed(options_.seed, 0, 0));
    return HideSearchState(pieces_, {first.slot_of, first.state});
  }
  // The greedy in a perturbed largest-first order (priorities first), as the iterated greedy does.
  Random random(stream_seed(options_.seed, static_cast<std::uint64_t>(restarts), 17));
  std::vector<int> units(pieces_.units.size());
  std::iota(units.begin(), units.end(), 0);
  const std::vector<int> order = perturbed_order(pieces_, units, random, true);
  const HideAssignment greedy = greedy_hides(instance_, pieces_, order, random.next());
  return HideSearchState(pieces_, {greedy.slot_of, greedy.state});
}

HidePlacement HideSearch::best_placement() {
  HideSearchState best = start(0);
  HideSearchState current = best;  // the trajectory searched now; best = the best state of all trajectories
  const auto offer = [&] {
    if (current.better_than(best)) {
      best = current;
      if (options_.on_improvement) options_.on_improvement(layout(best, false));
    }
  };
  if (options_.on_improvement) options_.on_improvement(layout(best, false));
  long streak = 0, restarts = 0;  // multi-hide attempts since the last success; trajectories started
  size_t regroup_count = 0;       // hides of the best layout when last counted
  long rounds_at_count = 0;       // rounds since the best layout's hide count changed
  std::vector<char> tried(pieces_.units.size(), 0);  // left-over units that failed since a hide was closed
  const std::vector<int> by_value = unit_order_by_value(pieces_);
  const HidePackingOracle oracle = search_hide_placement;
  // A new trajectory (from a perturbed greedy start, or regrouped); the best of all is kept.
  const auto begin_trajectory = [&](HideSearchState next) {
    current = std::move(next);
    streak = 0;
    std::fill(tried.begin(), tried.end(), 0);
    offer();
  };
  for (long round = 1; !options_.iteration_limit || round <= *options_.iteration_limit; ++round) {
    if (deadline_.passed()) break;
    const std::uint64_t seed = stream_seed(options_.seed, static_cast<std::uint64_t>(round), 0);
    // Once the moves have kept the best layout's hide count for tuning_.regroup_after_rounds rounds:
    // that layout regrouped onto one hide fewer (hide_regroup), once per hide count.
    if (const size_t count = best.used_slots().size(); count != regroup_count) {
      regroup_count = count;
      rounds_at_count = 0;
    }
    if (++rounds_at_count == tuning_.regroup_after_rounds) {
      if (auto fewer = regroup_fewer(best, round, context_, oracle)) {
        begin_trajectory(HideSearchState(pieces_, std::move(*fewer)));
        continue;
      }
      if (deadline_.passed()) break;
    }
    const std::vector<int> used = current.used_slots();
    HideSearchState trial = current;
    bool success = false;
    // Knapsack: a unit left over, most valuable first.
    int left_over = -1;
    for (int u : by_value)
      if (!tried[u] && current.slot_of()[pieces_.units[u].front()] < 0) {
        left_over = u;
        break;
      }
    if (left_over >= 0) {
      success = insert_left_over(trial, left_over, seed, context_);
      if (!success) tried[left_over] = 1;
    } else {
      // Multi-hide: fewer hides, until the budget. When the used hides are as few as their area
      // allows (or one hide holds everything that fits) only smaller hides are left to try.
      const bool at_area_bound = used.size() < 2 || used.size() <= current.area_bound();
      int level = 1;
      if (at_area_bound) {
        if (streak >= tuning_.shrink_tries) {
          // Every piece placed on as few hides as their area allows: done. Pieces left over (the
          // knapsack form, one hide): a new trajectory from a perturbed greedy start, as the iterated
          // greedy does, rather than ending with budget left (it ended after 3-10 s of 30 and placed
          // less area than the iterated greedy on some hides: docs/benchmarks-nest.md).
          if (!current.any_left_over()) break;
          begin_trajectory(start(++restarts));
          continue;
        }
      } else {
        const long cycles = streak / (tuning_.per_target * static_cast<long>(used.size()));
        // Stuck: a new trajectory from a perturbed greedy start. The search's outcome hangs on a few
        // lucky moves early on, so a trajectory that is behind the best gets one cycle, one as good
        // as the best every level of effort.
        if (cycles > (used.size() <= best.used_slots().size() ? tuning_.max_level : 0)) {
          begin_trajectory(start(++restarts));
          continue;
        }
        level = static_cast<int>(cycles);
      }
      const ScheduledMove next = scheduled_move(streak, level, at_area_bound);
      const MoveStep step{streak / 2, next.turn, seed, effort_at(level, tuning_)};
      success = hide_move(next.move).apply(trial, step, context_);
      streak = success ? 0 : streak + 1;
    }
    if (deadline_.passed()) break;  // a round cut short is not deterministic: drop it
    if (success) {
      const size_t used_before = used.size();
      current = std::move(trial);
      if (left_over < 0 && current.used_slots().size() < used_before) std::fill(tried.begin(), tried.end(), 0);
      offer();
    }
  }
  return best.placement();
}

}  // namespace

Layout nest_hides_search(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options) {
  return HideSearch(instance, pieces, options).run();
}

HidePlacement search_hide_placement(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options) {
  return HideSearch(instance, pieces, options).best_placement();
}

}  // namespace lastcut::nest_detail
