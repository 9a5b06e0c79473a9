#pragma once
// Separation of an overlapping layout by guided local search with several workers (sparrow: Gardeyn,
// Vanden Berghe & Wauters, arXiv:2509.13329, 2025, Algorithms 9 and 10). Every iteration each worker
// starts from the same layout and weights and sweeps it with its own random order and samples; the
// sweep that leaves the least weighted overlap is kept and the others are dropped. Then the weights
// are updated. A strike is a run of iterations that ends without a substantial (2 %) improvement on
// the overlap it started from; a substantial improvement also resets the count of iterations
// without improvement. It ends when no overlap is left, after max_strikes strikes, or at the deadline.
// The result depends only on the seeds and the worker count, not on how many threads run them: workers
// are compared by weighted overlap, ties going to the lowest index. More workers than cores still pays
// off where good moves are rare: each step then tries more sweeps of the same layout.
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "engine/nest/nest_random.hpp"
#include "engine/nest/separator.hpp"

namespace lastcut::nest_detail {

using RunParallel = std::function<void(std::vector<std::function<void()>>&)>;

class ParallelSeparation {
 public:
  // workers >= 1; worker w draws from a stream seeded by stream_seed(seed, 0, w). Each sweep hands
  // run_parallel min(tasks, workers) tasks, each sweeping the next worker not yet taken until none is
  // left (run_parallel unset: every worker on the caller's thread).
  ParallelSeparation(const std::vector<const PreparedItem*>& pieces, const Container& container, std::uint64_t seed,
                     int workers, int tasks, RunParallel run_parallel);

  void set_state(const std::vector<PieceState>& state) { lead().set_state(state); }
  const std::vector<PieceState>& state() const { return workers_.front()->state(); }
  double total_overlap() const { return workers_.front()->total_overlap(); }
  // Until feasible (true) or out of strikes or time, or once steps() reaches step_limit (false; the
  // least overlapping state is kept).
  bool separate(int max_strikes, int max_stale_iterations, const Deadline& deadline, long step_limit = kNoStepLimit);
  // Separation steps (sweeps of all workers) done so far by this object.
  long steps() const { return steps_; }
  static constexpr long kNoStepLimit = std::numeric_limits<long>::max();

 private:
  Separator& lead() { return *workers_.front(); }
  void sweep_all();

  std::vector<std::unique_ptr<Separator>> workers_;
  size_t tasks_;
  RunParallel run_parallel_;
  long steps_ = 0;
};

}  // namespace lastcut::nest_detail
