#include "engine/nest/overlap_proxy.hpp"

#include <algorithm>

namespace lastcut::nest_detail {

double pair_overlap(const OrientedShape& a, const Point2& offset_a, const OrientedShape& b, const Point2& offset_b,
                    double eps_mm, double stop_above) {
  // Pole pairs further apart than 3 eps add almost nothing: skip them without a square root,
  // and skip poles of a that do not reach b's box at all.
  const Point2 shift = offset_a - offset_b;
  const double reach = 3 * eps_mm;
  double total = eps_mm * eps_mm;  // colliding outlines overlap a little even where no poles meet
  for (const Pole& p : a.poles) {
    const Point2 c = p.center + shift;
    const double r = p.radius_mm + reach;
    if (c.x() + r < b.box.x0 || c.x() - r > b.box.x1 || c.y() + r < b.box.y0 || c.y() - r > b.box.y1) continue;
    for (const Pole& q : b.poles) {
      const double limit = r + q.radius_mm;
      const double d2 = (c - q.center).squaredNorm();
      if (d2 >= limit * limit) continue;
      const double pd = p.radius_mm + q.radius_mm - std::sqrt(d2);
      total += smoothed_depth(pd, eps_mm) * std::min(p.radius_mm, q.radius_mm);
    }
    if (total > stop_above) return total;
  }
  return total;
}

double rectangle_exterior_overlap(const OrientedShape& shape, const Point2& offset, const Box& inside, double eps_mm) {
  const Box world = shape.box.shifted(offset);
  if (inside.contains(world)) return 0;
  double total = 0, largest_radius = 0;
  for (const Pole& p : shape.poles) {
    const Point2 c = p.center + offset;
    const double depth_inside = std::min({c.x() - inside.x0, inside.x1 - c.x(), c.y() - inside.y0, inside.y1 - c.y()});
    total += smoothed_depth(p.radius_mm - depth_inside, eps_mm) * p.radius_mm;
    largest_radius = std::max(largest_radius, p.radius_mm);
  }
  const double protrusion = std::max(0.0, inside.x0 - world.x0) + std::max(0.0, world.x1 - inside.x1) +
                            std::max(0.0, inside.y0 - world.y0) + std::max(0.0, world.y1 - inside.y1);
  return total + protrusion * largest_radius;
}

}  // namespace lastcut::nest_detail
