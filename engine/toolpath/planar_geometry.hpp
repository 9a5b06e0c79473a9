#pragma once
// Small planar predicates the toolpath planner needs on closed polygons (mm).
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

// Even-odd point-in-polygon test (points on the boundary may go either way).
bool point_in_polygon(const Point2& point, const Polygon2& polygon);
// Distance (mm) from a point to the polygon's boundary, closing edge included.
double distance_to_boundary(const Point2& point, const Polygon2& polygon);
// True when the closed segments a-b and c-d share a point.
bool segments_intersect(const Point2& a, const Point2& b, const Point2& c, const Point2& d);
// Signed turn (radians, CCW positive, in (-pi, pi]) from direction `from` to direction `to`.
double signed_turn_rad(const Point2& from, const Point2& to);
// Removes consecutive points closer than min_step_mm (and, if closed, a last point equal to the first).
std::vector<Point2> without_repeated_points(const std::vector<Point2>& points_mm, double min_step_mm, bool closed);

}  // namespace lastcut
