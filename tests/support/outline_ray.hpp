#pragma once
// How far a ray goes before it crosses a closed outline: the tests' way to measure an allowance along
// an edge's normal on a cut line, independently of how the cut line was grown.
#include <cmath>

#include "engine/core/polygon.hpp"

namespace lastcut::test {

// From p along `direction` (unit) to the first crossing of the closed outline (mm); INFINITY when none.
inline double ray_to_outline(const Polygon2& outline, const Point2& p, const Point2& direction) {
  double nearest = INFINITY;
  for (std::size_t i = 0; i < outline.points.size(); ++i) {
    const Point2 a = outline.points[i], e = outline.points[(i + 1) % outline.points.size()] - a, w = a - p;
    const double det = direction.x() * e.y() - direction.y() * e.x();
    if (det == 0) continue;
    const double t = (w.x() * e.y() - w.y() * e.x()) / det, u = (w.x() * direction.y() - w.y() * direction.x()) / det;
    if (u >= 0 && u <= 1 && t > 1e-9) nearest = std::min(nearest, t);
  }
  return nearest;
}

}  // namespace lastcut::test
