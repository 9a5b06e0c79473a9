#include "engine/toolpath/arc_fit.hpp"

#include <cmath>
#include <numbers>
#include <optional>

#include "engine/toolpath/planar_geometry.hpp"

namespace lastcut {
namespace {

constexpr int kMaxRunPoints = 400;

struct Circle {
  Point2 center;
  double radius;
};

std::optional<Circle> circle_through(const Point2& a, const Point2& b, const Point2& c) {
  const double d = 2.0 * (a.x() * (b.y() - c.y()) + b.x() * (c.y() - a.y()) + c.x() * (a.y() - b.y()));
  if (std::abs(d) < 1e-12) return std::nullopt;
  const double a2 = a.squaredNorm(), b2 = b.squaredNorm(), c2 = c.squaredNorm();
  const Point2 center((a2 * (b.y() - c.y()) + b2 * (c.y() - a.y()) + c2 * (a.y() - b.y())) / d,
                      (a2 * (c.x() - b.x()) + b2 * (a.x() - c.x()) + c2 * (b.x() - a.x())) / d);
  return Circle{center, (a - center).norm()};
}

// Points first..last of the path fit one arc; returns the arc's direction when they do.
std::optional<bool> fits(const std::vector<Point2>& p, size_t first, size_t last, const Circle& circle,
                         const ArcFitOptions& options) {
  if (circle.radius > options.max_radius_mm) return std::nullopt;
  const double turn0 = signed_turn_rad(p[first] - circle.center, p[first + 1] - circle.center);
  const bool ccw = turn0 > 0.0;
  double swept = 0.0;
  for (size_t k = first; k < last; ++k) {
    const Point2 from = p[k] - circle.center, to = p[k + 1] - circle.center;
    const double turn = signed_turn_rad(from, to);
    if ((turn > 0.0) != ccw || std::abs(turn) > std::numbers::pi / 2) return std::nullopt;
    swept += std::abs(turn);
    if (std::abs((p[k + 1] - circle.center).norm() - circle.radius) > options.tolerance_mm) return std::nullopt;
    // The chord's midpoint sits the sagitta inside the arc: it must stay within tolerance too.
    const double sagitta = circle.radius * (1.0 - std::cos(0.5 * std::abs(turn)));
    if (sagitta > options.tolerance_mm) return std::nullopt;
  }
  if (swept > 1.9 * std::numbers::pi) return std::nullopt;
  return ccw;
}

}  // namespace

std::vector<PathSegment> fit_arcs(const std::vector<Point2>& points_mm, const ArcFitOptions& options) {
  std::vector<PathSegment> segments;
  const auto& p = points_mm;
  size_t i = 0;
  while (i + 1 < p.size()) {
    size_t best_last = i;
    PathSegment best;
    const size_t min_last = i + static_cast<size_t>(options.min_points) - 1;
    for (size_t last = min_last; last < p.size() && last - i < kMaxRunPoints; ++last) {
      const auto circle = circle_through(p[i], p[(i + last) / 2], p[last]);
      if (!circle) break;
      const auto ccw = fits(p, i, last, *circle, options);
      if (!ccw) break;
      best_last = last;
      best = PathSegment{true, p[last], circle->center, *ccw};
    }
    if (best_last > i) {
      segments.push_back(best);
      i = best_last;
    } else {
      segments.push_back(PathSegment{false, p[i + 1], Point2::Zero(), false});
      ++i;
    }
  }
  return segments;
}

}  // namespace lastcut
