#pragma once
// Polygon2: a closed planar polygon in millimetres. The closing edge is implicit
// (the last point is not repeated). Molds are counter-clockwise and simple.
#include <Eigen/Core>
#include <vector>

namespace lastcut {

using Point2 = Eigen::Vector2d;

struct Polygon2 {
  std::vector<Point2> points;  // mm
};

// Signed area (mm^2): positive for counter-clockwise.
double signed_area(const Polygon2& polygon);
// Perimeter including the closing edge (mm).
double perimeter(const Polygon2& polygon);
// Reverses the order of the points when the polygon is clockwise.
void make_counter_clockwise(Polygon2& polygon);
// Distance (mm) from a point to the closed segment a-b (a point when a == b).
double distance_to_segment(const Point2& point, const Point2& a, const Point2& b);

}  // namespace lastcut
