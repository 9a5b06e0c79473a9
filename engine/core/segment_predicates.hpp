#pragma once
// Orientation predicates on points and closed segments in the plane (mm), shared by the mold
// outline checks, the hide file checks, the nester's collision test and the toolpath labels.
// The signs of the floating-point cross products are taken as they are, without a tolerance: two
// segments a rounding error apart do not touch, a collinear overlap is seen only when the cross
// products are exactly zero. Every caller thus gets the same answer for the same coordinates.
// Inline: the nester calls segments_touch in its innermost loop.
#include <algorithm>
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

// Sign of the cross product (a - o) x (b - o): +1 when o, a, b turn counter-clockwise,
// -1 clockwise, 0 when they are exactly collinear (or two of them coincide).
inline int orientation(const Point2& o, const Point2& a, const Point2& b) {
  const double cross = (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  return (cross > 0) - (cross < 0);
}

// p, known to be collinear with a-b, lies within the segment (its bounding box).
inline bool collinear_point_on_segment(const Point2& p, const Point2& a, const Point2& b) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
         p.y() <= std::max(a.y(), b.y());
}

// The closed segments a-b and c-d share at least one point: they cross, an end point lies on the
// other segment, or they overlap collinearly. A segment of zero length is its point.
inline bool segments_touch(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const int d1 = orientation(c, d, a), d2 = orientation(c, d, b);
  const int d3 = orientation(a, b, c), d4 = orientation(a, b, d);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && collinear_point_on_segment(a, c, d)) || (d2 == 0 && collinear_point_on_segment(b, c, d)) ||
         (d3 == 0 && collinear_point_on_segment(c, a, b)) || (d4 == 0 && collinear_point_on_segment(d, a, b));
}

// Crossing-number (even-odd) test of `point` against the closed ring #R (mm, either orientation,
// the closing edge implicit); a point on the boundary may go either way. Precondition: #R >= 1.
inline bool point_in_ring(const Point2& point, const std::vector<Point2>& ring) {
  bool inside = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Point2& a = ring[i];
    const Point2& b = ring[j];
    if ((a.y() > point.y()) != (b.y() > point.y()) &&
        point.x() < (b.x() - a.x()) * (point.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

}  // namespace lastcut
