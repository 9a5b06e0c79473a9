#pragma once
// Options of the nester. The engine starts no threads: parallel work is handed to run_parallel,
// which the caller (the CLI, the daemon) may implement with std::thread. The result depends only on
// the instance, seed and sweep_workers when iteration_limit or sweep_limit bounds the search, not on the number of
// threads; the time limit only stops it early (a stopped round is thrown away, so what is returned
// was reached deterministically). Hides: on the instance, seed and threads.
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "engine/nest/layout.hpp"

namespace lastcut {

// How hides are nested (engine/nest/hide_nester.hpp): the overlap-minimising search, or the older
// greedy + iterated greedy (kept for comparison).
enum class HideMethod { Search, Greedy };

struct NestOptions {
  double time_limit_s = 10;              // wall-clock budget of the improvement phase
  std::uint64_t seed = 1;                // worker w of round r draws from a stream seeded by (seed, r, w)
  int threads = 1;                       // tasks handed to run_parallel at once (hides: attempts per round)
  // Strips: workers that sweep the same layout in every separation step, the best sweep kept
  // (sparrow's Algorithm 10, which uses 3). More sweeps per step help where good moves are rare;
  // the choice of four is measured in docs/benchmarks-nest.md.
  int sweep_workers = 4;
  std::optional<double> gap_mm;          // overrides NestInstance::gap_mm
  std::optional<double> margin_mm;       // overrides NestInstance::margin_mm
  std::optional<long> iteration_limit;   // improvement rounds; unset = until the time limit
  // Strips: separation steps (one sweep of every worker each), a budget proportional to the work done
  // however long a round takes (a failed separation costs a hundred times a successful one); the
  // exploration gets the first 80 % of the steps. Deterministic like iteration_limit, so two versions
  // of the search can be compared on the same work under any machine load. Unset: no such bound.
  std::optional<long> sweep_limit;
  double free_rotation_step_deg = 15;    // step of the rotations tried for freely rotating pieces
  HideMethod hide_method = HideMethod::Search;
  // Called on the caller's thread with every better layout (anytime: the first one comes early).
  std::function<void(const Layout&)> on_improvement;
  // Runs every task and returns when all are done. Unset: one after the other on the caller's thread.
  std::function<void(std::vector<std::function<void()>>&)> run_parallel;
};

}  // namespace lastcut
