#pragma once
// ARAP from the boundary-first start (the default) against the plane-rotation start, on the same halves
// in the same run: iterations, seconds, final energy, and how far each result's outline lies from the
// converged map's (ARAP run to 2000 iterations or an energy change of 1e-12), after the best rigid
// alignment. The last column is what a pattern maker sees: an unconverged map has a different outline.
#include <vector>

#include "bench/flatten/bench_halves.hpp"

namespace lastcut::bench {

// Prints a markdown table, one row per half and start.
void print_start_comparison(const std::vector<BenchHalf>& halves);

}  // namespace lastcut::bench
