#pragma once
// Strip packing: fixed height, minimise the length. A sampled left-most greedy start, then strip
// shrinking: shorten the strip, push out-of-bounds pieces in, and remove the overlaps by guided local
// search (Separator); a success becomes the new best layout, a failure shrinks less next time.
// Method after sparrow (Gardeyn, Vanden Berghe & Wauters, arXiv:2509.13329, 2025) and the
// shrink-and-separate loop of Imamichi, Yagiura & Nagamochi (2009).
#include "engine/nest/layout.hpp"
#include "engine/nest/nest_options.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut {

// instance.strip_height must be set. Every copy of every item is placed or listed in unplaced.
Layout nest_strip(const NestInstance& instance, const NestOptions& options);

}  // namespace lastcut
