#include "engine/nest/hide_nester.hpp"

#include <algorithm>
#include <numeric>

#include "engine/nest/hide_greedy.hpp"
#include "engine/nest/hide_search.hpp"
#include "engine/nest/nest_random.hpp"

namespace lastcut {
namespace {

using namespace nest_detail;

Layout nest_hides_greedy(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options) {
  const Deadline deadline(options.time_limit_s);
  const std::vector<int> order = unit_order_by_value(pieces);
  HideAssignment best = greedy_hides(instance, pieces, order, stream_seed(options.seed, 0, 0));
  if (options.on_improvement) options.on_improvement(finish_hides(instance, pieces, best.slot_of, best.state, false, options.seed));

  std::vector<int> units(pieces.units.size());
  std::iota(units.begin(), units.end(), 0);
  const int threads = std::max(1, options.threads);
  std::vector<HideAssignment> results(threads);
  for (long round = 1; !pieces.units.empty() && (!options.iteration_limit || round <= *options.iteration_limit); ++round) {
    if (deadline.passed()) break;
    std::vector<std::function<void()>> tasks;
    for (int w = 0; w < threads; ++w) {
      tasks.push_back([&, w, round] {
        Random random(stream_seed(options.seed, round, w));
        const std::vector<int> perturbed = perturbed_order(pieces, units, random, true);
        results[w] = greedy_hides(instance, pieces, perturbed, random.next());
      });
    }
    if (options.run_parallel) {
      options.run_parallel(tasks);
    } else {
      for (auto& task : tasks) task();
    }
    if (deadline.passed()) break;  // a round cut short is not deterministic: drop it
    int winner = -1;
    for (int w = 0; w < threads; ++w)
      if (results[w].better_than(winner < 0 ? best : results[winner])) winner = w;
    if (winner >= 0) {
      best = results[winner];
      if (options.on_improvement) options.on_improvement(finish_hides(instance, pieces, best.slot_of, best.state, false, options.seed));
    }
  }
  return finish_hides(instance, pieces, best.slot_of, best.state, true, options.seed);
}

}  // namespace

Layout nest_hides(const NestInstance& instance, const NestOptions& options) {
  const HidePieces pieces = prepare_hide_pieces(instance, options);
  if (options.hide_method == HideMethod::Greedy) return nest_hides_greedy(instance, pieces, options);
  return nest_hides_search(instance, pieces, options);
}

}  // namespace lastcut
