#pragma once
// Nesting on hides and sheets: every piece if possible, on as few hides as possible (multi-hide form),
// or the most valuable pieces when not all fit (knapsack form: priority first, then area).
// Two methods (NestOptions::hide_method):
// - Search (default, engine/nest/hide_search): a greedy start, then the overlap-minimising search of
//   the strip nester inside each hide: empty the least-filled hide into the others by separation,
//   insert pieces left over by separation (sparrow: Gardeyn, Vanden Berghe & Wauters,
//   arXiv:2509.13329, 2025; Egeblad, Nielsen & Odgaard 2007).
// - Greedy: hides in order of price per usable area (largest first on a tie), pieces largest first,
//   each at the sampled feasible spot furthest to the left, refined by sliding; under the time limit
//   iterated greedy (Ruiz & Stuetzle 2007) over the piece order - every round each worker rebuilds
//   from a perturbed order and the best layout by (area placed, hides used, length of the packings)
//   is kept. Kept for comparison (bench/nest).
// Both honour grain vs a hide's backbone, quality regions and pair groups (engine/nest/hide_pieces).
#include "engine/nest/layout.hpp"
#include "engine/nest/nest_options.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut {

// instance.bins must not be empty. Every copy of every item is placed or listed in unplaced.
Layout nest_hides(const NestInstance& instance, const NestOptions& options);

}  // namespace lastcut
