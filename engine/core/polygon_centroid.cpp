#include "engine/core/polygon_centroid.hpp"

#include <cmath>

namespace lastcut {

Point2 area_centroid(const Polygon2& polygon) {
  const auto& p = polygon.points;
  Point2 sum = Point2::Zero();
  double twice_area = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Point2& a = p[i];
    const Point2& b = p[(i + 1) % p.size()];
    const double w = a.x() * b.y() - b.x() * a.y();
    sum += w * (a + b);
    twice_area += w;
  }
  return twice_area != 0.0 ? Point2(sum / (3.0 * twice_area)) : p.front();
}

Point2 principal_axis(const Polygon2& polygon) {
  const Point2 centroid = area_centroid(polygon);
  double xx = 0.0, xy = 0.0, yy = 0.0;
  const auto& p = polygon.points;
  for (size_t i = 0; i < p.size(); ++i) {
    const Point2 a = p[i] - centroid, b = p[(i + 1) % p.size()] - centroid;
    const double cross = a.x() * b.y() - b.x() * a.y();
    xx += cross * (a.x() * a.x() + a.x() * b.x() + b.x() * b.x());
    yy += cross * (a.y() * a.y() + a.y() * b.y() + b.y() * b.y());
    xy += cross * (2 * a.x() * a.y() + a.x() * b.y() + b.x() * a.y() + 2 * b.x() * b.y());
  }
  xy *= 0.5;  // the common factor 1/12 does not change the axis; a clockwise ring gives all three negated
  if (signed_area(polygon) < 0.0) xx = -xx, xy = -xy, yy = -yy;
  const double angle = 0.5 * std::atan2(2.0 * xy, xx - yy);
  return {std::cos(angle), std::sin(angle)};
}

}  // namespace lastcut
