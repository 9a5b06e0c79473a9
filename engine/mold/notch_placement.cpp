// Notch placement on a mold's outline; see notch_placement.hpp.
#include "engine/mold/notch_placement.hpp"

#include <cmath>
#include <limits>

#include "engine/mold/outline_geometry.hpp"

namespace lastcut {

MoldMark notch_at(const std::string& name, const Polygon2& outline, const Point2& landmark) {
  const OutlinePoint nearest = closest_outline_point(outline, landmark);
  const auto& q = outline.points;
  const int n = static_cast<int>(q.size());
  Point2 inward = inward_normal(outline, nearest.edge);
  // At a corner the notch bisects the two edges it joins.
  constexpr double kAtVertex_mm = 1e-9;
  if ((nearest.point - q[nearest.edge]).norm() < kAtVertex_mm)
    inward += inward_normal(outline, (nearest.edge + n - 1) % n);
  else if ((nearest.point - q[(nearest.edge + 1) % n]).norm() < kAtVertex_mm)
    inward += inward_normal(outline, (nearest.edge + 1) % n);
  if (inward.norm() > 0.0) inward.normalize();
  return {name, nearest.point, inward};
}

MoldMark notch_along_normal(const std::string& name, const Polygon2& outline, const Point2& net_point,
                            const Point2& outward) {
  const auto& q = outline.points;
  const size_t n = q.size();
  double best_t = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < n; ++i) {
    const Point2 a = q[i], b = q[(i + 1) % n];
    const Point2 ab = b - a;
    const double denominator = outward.x() * ab.y() - outward.y() * ab.x();
    if (denominator == 0.0) continue;
    const Point2 ap = a - net_point;
    const double t = (ap.x() * ab.y() - ap.y() * ab.x()) / denominator;         // along the normal
    const double u = (ap.x() * outward.y() - ap.y() * outward.x()) / denominator;  // along the edge
    // The zero-allowance edges of a grown outline are the net rounded to Clipper's 10 nm grid.
    constexpr double kOnOutline_mm = 1e-4;
    if (t >= -kOnOutline_mm && u >= 0.0 && u <= 1.0 && t < best_t) best_t = t;
  }
  if (!std::isfinite(best_t) || outward.norm() == 0.0) return notch_at(name, outline, net_point);
  return {name, net_point + best_t * outward, -outward};
}

}  // namespace lastcut
