#include "engine/toolpath/planar_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lastcut {
namespace {

double cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

bool on_segment(const Point2& p, const Point2& a, const Point2& b) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

int orientation(const Point2& a, const Point2& b, const Point2& c) {
  const double value = cross(b - a, c - a);
  if (value > 0) return 1;
  if (value < 0) return -1;
  return 0;
}

}  // namespace

bool point_in_polygon(const Point2& point, const Polygon2& polygon) {
  bool inside = false;
  const auto& p = polygon.points;
  for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    const bool crosses = (p[i].y() > point.y()) != (p[j].y() > point.y());
    if (crosses) {
      const double x_at = p[j].x() + (point.y() - p[j].y()) * (p[i].x() - p[j].x()) / (p[i].y() - p[j].y());
      if (point.x() < x_at) inside = !inside;
    }
  }
  return inside;
}

double distance_to_boundary(const Point2& point, const Polygon2& polygon) {
  double best = std::numeric_limits<double>::infinity();
  const auto& p = polygon.points;
  for (size_t i = 0; i < p.size(); ++i) best = std::min(best, distance_to_segment(point, p[i], p[(i + 1) % p.size()]));
  return best;
}

bool segments_intersect(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 != o2 && o3 != o4) return true;
  if (o1 == 0 && on_segment(c, a, b)) return true;
  if (o2 == 0 && on_segment(d, a, b)) return true;
  if (o3 == 0 && on_segment(a, c, d)) return true;
  if (o4 == 0 && on_segment(b, c, d)) return true;
  return false;
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
