#pragma once
// Small planar helpers the toolpath planner needs on closed polygons (mm); the point and segment
// predicates are engine/core/segment_predicates.hpp.
#include <vector>

#include "engine/core/polygon.hpp"
#include "engine/core/segment_predicates.hpp"

namespace lastcut {

// Distance (mm) from a point to the polygon's boundary, closing edge included.
double distance_to_boundary(const Point2& point, const Polygon2& polygon);
// Signed turn (radians, CCW positive, in (-pi, pi]) from direction `from` to direction `to`.
double signed_turn_rad(const Point2& from, const Point2& to);
// Removes consecutive points closer than min_step_mm (and, if closed, a last point equal to the first).
std::vector<Point2> without_repeated_points(const std::vector<Point2>& points_mm, double min_step_mm, bool closed);

}  // namespace lastcut
