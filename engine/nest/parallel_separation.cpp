#include "engine/nest/parallel_separation.hpp"

#include <algorithm>
#include <atomic>

namespace lastcut::nest_detail {

ParallelSeparation::ParallelSeparation(const std::vector<const PreparedItem*>& pieces, const Container& container,
                                       std::uint64_t seed, int workers, int tasks, RunParallel run_parallel)
    : tasks_(static_cast<size_t>(std::clamp(tasks, 1, std::max(1, workers)))), run_parallel_(std::move(run_parallel)) {
  for (int w = 0; w < std::max(1, workers); ++w)
    workers_.push_back(std::make_unique<Separator>(pieces, container, stream_seed(seed, 0, w)));
}

void ParallelSeparation::sweep_all() {
  ++steps_;
  if (workers_.size() == 1) {
    lead().sweep();
    return;
  }
  for (size_t w = 1; w < workers_.size(); ++w) workers_[w]->adopt(lead());
  // Each task takes the next worker not yet taken, so a thread that finishes a short sweep early
  // takes another instead of waiting for a fixed partner. Which thread sweeps a worker does not
  // matter: a worker's sweep depends only on its own state and random stream.
  std::atomic<size_t> next{0};
  std::vector<std::function<void()>> tasks;
  for (size_t t = 0; t < tasks_; ++t)
    tasks.push_back([this, &next] {
      for (size_t w = next++; w < workers_.size(); w = next++) workers_[w]->sweep();
    });
  if (run_parallel_ && tasks.size() > 1) {
    run_parallel_(tasks);
  } else {
    for (auto& task : tasks) task();
  }
  size_t winner = 0;
  double least = workers_[0]->total_weighted_overlap();
  for (size_t w = 1; w < workers_.size(); ++w) {
    const double overlap = workers_[w]->total_weighted_overlap();
    if (overlap < least) least = overlap, winner = w;
  }
  if (winner > 0) lead().adopt(*workers_[winner]);
}

bool ParallelSeparation::separate(int max_strikes, int max_stale_iterations, const Deadline& deadline, long step_limit) {
  lead().reset_weights();
  double best_total = lead().total_overlap();
  if (best_total == 0) return true;
  std::vector<PieceState> best_state = lead().state();
  constexpr double kSubstantial = 0.98;
  for (int strike = 0; strike < max_strikes;) {
    const double strike_start = lead().total_overlap();
    for (int stale = 0; stale < max_stale_iterations;) {
      if (deadline.passed() || steps_ >= step_limit) {
        lead().set_state(best_state);
        return false;
      }
      sweep_all();
      const double total = lead().total_overlap();
      if (total == 0) return true;
      if (total < best_total) {
        if (total < kSubstantial * best_total) stale = 0;
        best_total = total, best_state = lead().state();
      } else {
        ++stale;
      }
      lead().update_weights();
    }
    strike = best_total < kSubstantial * strike_start ? 0 : strike + 1;
    lead().set_state(best_state);  // back to the least overlap, keeping the weights learnt so far
  }
  return false;
}

}  // namespace lastcut::nest_detail
