#pragma once
// Nesting on hides and sheets: every piece if possible, on as few hides as possible, packed towards
// one side of each hide. Construction: hides in order of price per usable area (largest first on a
// tie), pieces largest first, each at the sampled feasible spot (exact test against the hide outline,
// defects and forbidden quality zones) furthest to the left, refined by sliding. Improvement under
// the time limit: iterated greedy (Ruiz & Stuetzle 2007) over the piece order - every round each
// worker rebuilds from a perturbed order and the best layout by (area placed, hides used, length of
// the last hide's packing) is kept.
#include "engine/nest/layout.hpp"
#include "engine/nest/nest_options.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut {

// instance.bins must not be empty. Every copy of every item is placed or listed in unplaced.
Layout nest_hides(const NestInstance& instance, const NestOptions& options);

}  // namespace lastcut
