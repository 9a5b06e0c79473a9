#pragma once
// Simplification of a closed simple outline by Douglas-Peucker (Douglas & Peucker 1973,
// Cartographica 10(2) 112-122) that never introduces a self-intersection: after the classic pass,
// every kept chord that crosses another is split again at its farthest dropped point, until the
// outline is simple. The input is simple, so this ends at the latest with the input itself.
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

// polygon: closed, simple, mm. tolerance_mm >= 0: every dropped point lies within tolerance_mm of
// the edge of the result that replaces it. keep: indices that must survive (landmarks).
// Returns the indices (increasing) of the kept points of polygon.
std::vector<int> simplify_outline(const Polygon2& polygon, double tolerance_mm, const std::vector<int>& keep = {});

// The polygon made of the given point indices.
Polygon2 select_points(const Polygon2& polygon, const std::vector<int>& indices);

}  // namespace lastcut
