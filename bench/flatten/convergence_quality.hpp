#pragma once
// Speed and quality of the default ARAP flattening on the same halves, in one table: wall seconds of
// flatten() (min and median of `runs`), its stages, and how far the result lies from the fully
// converged map (ARAP to an energy change of 1e-12 or 3000 iterations): the outline's largest and rms
// distance after the best rigid alignment (a mold is cut to ~0.1 mm), D_angle/D_area of both maps, and
// flipped triangles. `--trace` adds the outline distance after exactly 5, 10, ... iterations (energy
// tolerance 0) until it is within 0.05 mm: how many iterations a 0.1 mm mold needs, which is what a
// stopping rule has to be judged by.
#include <vector>

#include "bench/flatten/bench_halves.hpp"

namespace lastcut::bench {

// One row per half.
void print_convergence_quality(const std::vector<BenchHalf>& halves, int runs);

// One row per half and iteration count: the outline distance to the converged map after that many iterations.
void print_outline_by_iteration(const std::vector<BenchHalf>& halves);

}  // namespace lastcut::bench
