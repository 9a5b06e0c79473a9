// Open 3D polylines; see polyline_3d.hpp.
#include "engine/core/polyline_3d.hpp"

#include <algorithm>
#include <cmath>

namespace lastcut {

double polyline_length_mm(const Polyline3& polyline) {
  double length = 0;
  for (std::size_t i = 1; i < polyline.size(); ++i) length += (polyline[i] - polyline[i - 1]).norm();
  return length;
}

PolylineHit closest_on_polyline(const Eigen::Vector3d& p, const Polyline3& polyline) {
  PolylineHit best{(p - polyline.front()).norm(), 0, polyline.front()};
  double along = 0;
  for (std::size_t i = 1; i < polyline.size(); ++i) {
    const Eigen::Vector3d ab = polyline[i] - polyline[i - 1];
    const double t = std::clamp((p - polyline[i - 1]).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    const Eigen::Vector3d q = polyline[i - 1] + t * ab;
    if ((q - p).norm() < best.distance_mm) best = {(q - p).norm(), along + t * ab.norm(), q};
    along += ab.norm();
  }
  return best;
}

Eigen::Vector3d point_at_arc_length(const Polyline3& polyline, double s_mm) {
  double along = 0;
  for (std::size_t i = 1; i < polyline.size(); ++i) {
    const double step = (polyline[i] - polyline[i - 1]).norm();
    if (along + step >= s_mm && step > 0)
      return polyline[i - 1] + (polyline[i] - polyline[i - 1]) * std::clamp((s_mm - along) / step, 0.0, 1.0);
    along += step;
  }
  return s_mm <= 0 ? polyline.front() : polyline.back();
}

}  // namespace lastcut
