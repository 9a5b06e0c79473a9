#include "engine/toolpath/piece_contour.hpp"

#include <cmath>
#include <numbers>

#include "engine/toolpath/planar_geometry.hpp"

namespace lastcut {
namespace {

// Turn (deg) at vertex i of a CCW polygon: positive at convex corners.
double turn_deg(const Polygon2& outline, size_t i) {
  const auto& p = outline.points;
  const size_t n = p.size();
  const Point2 incoming = p[i] - p[(i + n - 1) % n];
  const Point2 outgoing = p[(i + 1) % n] - p[i];
  if (incoming.norm() == 0.0 || outgoing.norm() == 0.0) return 0.0;
  return signed_turn_rad(incoming, outgoing) * 180.0 / std::numbers::pi;
}

int sharpest_corner(const Polygon2& outline, double corner_min_deg) {
  int best = -1;
  double best_turn_deg = corner_min_deg;
  for (size_t i = 0; i < outline.points.size(); ++i) {
    const double turn = turn_deg(outline, i);
    if (turn > best_turn_deg + 1e-9) {
      best_turn_deg = turn;
      best = static_cast<int>(i);
    }
  }
  return best;
}

}  // namespace

bool has_start_corner(const Polygon2& outline, double corner_min_deg) {
  return sharpest_corner(outline, corner_min_deg) >= 0;
}

int contour_start_vertex(const Polygon2& outline, const Point2& preferred_mm, double corner_min_deg) {
  const int corner = sharpest_corner(outline, corner_min_deg);
  if (corner >= 0) return corner;
  int nearest = 0;
  for (size_t i = 1; i < outline.points.size(); ++i) {
    if ((outline.points[i] - preferred_mm).squaredNorm() < (outline.points[nearest] - preferred_mm).squaredNorm()) {
      nearest = static_cast<int>(i);
    }
  }
  return nearest;
}

std::vector<Point2> contour_cut_path(const Polygon2& outline, int start_vertex, double overcut_mm) {
  const auto& p = outline.points;
  const size_t n = p.size();
  std::vector<Point2> path;
  path.reserve(n + 4);
  for (size_t k = 0; k <= n; ++k) path.push_back(p[(start_vertex + k) % n]);
  double remaining_mm = overcut_mm;
  for (size_t k = 0; k < n && remaining_mm > 1e-9; ++k) {
    const Point2& a = p[(start_vertex + k) % n];
    const Point2& b = p[(start_vertex + k + 1) % n];
    const double edge_mm = (b - a).norm();
    if (edge_mm >= remaining_mm) {
      path.push_back(a + (b - a) * (remaining_mm / edge_mm));
      break;
    }
    path.push_back(b);
    remaining_mm -= edge_mm;
  }
  return path;
}

}  // namespace lastcut
