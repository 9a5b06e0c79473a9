#pragma once
// Planar geometry on outlines: simplicity test, point-to-outline distance, closest point.
#include <optional>
#include <utility>

#include "engine/core/polygon.hpp"

namespace lastcut {

// First pair of non-adjacent edges (i, j) of the closed polygon that touch or cross, if any;
// edge i runs from point i to point i+1. Uses a uniform grid, about O(n) for outlines.
std::optional<std::pair<int, int>> find_self_intersection(const Polygon2& polygon);

// Every pair of intersecting non-adjacent edges (for repairing a simplification).
std::vector<std::pair<int, int>> find_self_intersections(const Polygon2& polygon);

inline bool is_simple(const Polygon2& polygon) { return !find_self_intersection(polygon).has_value(); }

struct OutlinePoint {
  Point2 point = Point2::Zero();  // closest point on the outline (mm)
  int edge = 0;                   // edge index it lies on
  double distance_mm = 0.0;
};
// Closest point of the closed polygon's edges to p (brute force, O(n)).
OutlinePoint closest_outline_point(const Polygon2& polygon, const Point2& p);

// Unit normal pointing into a counter-clockwise polygon at the given edge.
Point2 inward_normal(const Polygon2& polygon, int edge);

}  // namespace lastcut
