#include "engine/toolpath/planar_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lastcut {
namespace {

double cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

double distance_to_boundary(const Point2& point, const Polygon2& polygon) {
  double best = std::numeric_limits<double>::infinity();
  const auto& p = polygon.points;
  for (size_t i = 0; i < p.size(); ++i) best = std::min(best, distance_to_segment(point, p[i], p[(i + 1) % p.size()]));
  return best;
}

double signed_turn_rad(const Point2& from, const Point2& to) { return std::atan2(cross(from, to), from.dot(to)); }

std::vector<Point2> without_repeated_points(const std::vector<Point2>& points_mm, double min_step_mm, bool closed) {
  std::vector<Point2> kept;
  for (const Point2& point : points_mm) {
    if (kept.empty() || (point - kept.back()).norm() >= min_step_mm) kept.push_back(point);
  }
  while (closed && kept.size() > 1 && (kept.back() - kept.front()).norm() < min_step_mm) kept.pop_back();
  return kept;
}

}  // namespace lastcut
