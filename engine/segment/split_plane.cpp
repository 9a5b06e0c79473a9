#include "engine/segment/split_plane.hpp"

#include <Eigen/Geometry>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

Eigen::Vector3d mean_of(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}

}  // namespace

SplitPlane split_plane(const std::vector<Eigen::Vector3d>& lower, const std::vector<Eigen::Vector3d>& upper, double t,
                       FootSide side) {
  if (lower.size() < 3 || upper.size() < 3) throw EngineError("the sole or top contour is too short to place the split plane");
  if (!(t > 0.0 && t < 0.5)) throw EngineError("the split plane parameter t must lie between 0 and 1/2");
  std::size_t ia = 0, ib = 0;
  double farthest = -1.0;
  for (std::size_t i = 0; i < lower.size(); ++i)
    for (std::size_t j = i + 1; j < lower.size(); ++j) {
      const double d = (lower[i] - lower[j]).squaredNorm();
      if (d > farthest) { farthest = d; ia = i; ib = j; }
    }
  // Let A be the toe end so T2 is the front point (only a naming convention; the plane is the same).
  if (lower[ia].x() < lower[ib].x()) std::swap(ia, ib);
  const Eigen::Vector3d A = lower[ia], B = lower[ib];
  // delta(t, C) = (C - A(1-t) - Bt) . (A - B)
  auto delta = [&](double s, const Eigen::Vector3d& C) { return (C - A * (1.0 - s) - B * s).dot(A - B); };
  std::vector<Eigen::Vector3d> near_a, near_b;
  for (const Eigen::Vector3d& C : lower) {
    if (delta(t, C) > 0.0) near_a.push_back(C);        // M1, eq. 14
    if (delta(1.0 - t, C) < 0.0) near_b.push_back(C);  // M2, eq. 15
  }
  if (near_a.empty() || near_b.empty()) throw EngineError("the sole contour has no points near its toe or heel end");
  SplitPlane plane;
  plane.T1 = mean_of(upper);
  plane.T2 = mean_of(near_a);
  plane.T3 = mean_of(near_b);
  // Eqs. 17-19 expand the determinant with rows (T2 - T1) and (T3 - T2): the normal is their cross product.
  const Eigen::Vector3d normal = (plane.T2 - plane.T1).cross(plane.T3 - plane.T2);
  const double length = normal.norm();
  if (length < 1e-6 * (plane.T2 - plane.T3).squaredNorm())
    throw EngineError("the top centre lies on the toe-heel line: cannot place the split plane");
  plane.normal = normal / length;
  if (plane.normal.y() * medial_y_sign(side) < 0.0) plane.normal = -plane.normal;
  plane.offset = -plane.normal.dot(plane.T1);  // eq. 20
  return plane;
}

}  // namespace lastcut
