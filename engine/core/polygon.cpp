#include "engine/core/polygon.hpp"

#include <algorithm>

namespace lastcut {

double signed_area(const Polygon2& polygon) {
  const auto& p = polygon.points;
  double twice_area = 0.0;
  for (size_t i = 0, n = p.size(); i < n; ++i) {
    const Point2& a = p[i];
    const Point2& b = p[(i + 1) % n];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice_area;
}

double perimeter(const Polygon2& polygon) {
  const auto& p = polygon.points;
  double length = 0.0;
  for (size_t i = 0, n = p.size(); i < n; ++i) length += (p[(i + 1) % n] - p[i]).norm();
  return length;
}

void make_counter_clockwise(Polygon2& polygon) {
  if (signed_area(polygon) < 0.0) std::reverse(polygon.points.begin(), polygon.points.end());
}

double distance_to_segment(const Point2& point, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  const double length_squared = ab.squaredNorm();
  const double t = length_squared > 0.0 ? std::clamp((point - a).dot(ab) / length_squared, 0.0, 1.0) : 0.0;
  return (a + t * ab - point).norm();
}

}  // namespace lastcut
