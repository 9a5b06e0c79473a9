#include "engine/core/polygon_centroid.hpp"

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

}  // namespace lastcut
