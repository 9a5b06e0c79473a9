#pragma once
// An independent exact check of a layout, built on Clipper's polygon booleans (Clipper 6.4,
// Angus Johnson) on integer coordinates, sharing no code with the nester's collision detection.
// It checks: every placement names a known item (and hide on hides); each item is placed at most its
// demand and placed + unplaced = demand; rotations are allowed ones, mirroring only where allowed;
// the grain lies within tolerance of the material's grain (a hide's backbone when it has one, else the
// x axis); pieces lie inside the strip or hide (at least `margin` from its edge and from defects),
// outside zones below their min_quality, each quality region outside zones below its own min_quality;
// the pieces of a pair group are all placed or none, on one hide, each with its centroid near another's
// (NestInstance::pair_distance_mm, or the mean of their bounding box diagonals plus the gap); no two pieces come closer than `gap`
// (each grown by gap/2, pairwise intersections must be empty); the strip length and utilisation are right.
// Numerical tolerance: intersections below 1e-8 of the smaller piece's area count as empty.
#include <string>
#include <vector>

#include "engine/nest/layout.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut {

// One line per problem found; empty when the layout is valid. gap/margin: instance values when negative.
std::vector<std::string> check_layout(const Layout& layout, const NestInstance& instance, double gap_mm = -1,
                                      double margin_mm = -1);

}  // namespace lastcut
