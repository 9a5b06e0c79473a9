#include "engine/segment/split_plane.hpp"

#include <Eigen/Geometry>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

// Centroid of a closed polyline as a curve (arc-length weighted), restricted to the part where the
// affine function side(p) >= 0. Each edge is clipped exactly at side = 0, so the result does not
// depend on how densely the curve is sampled: a vertex average would move towards wherever the
// mesh happens to have more vertices. Returns false when no length lies on that side.
template <typename Side>
bool curve_centroid(const std::vector<Eigen::Vector3d>& loop, Side side, Eigen::Vector3d& centroid) {
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  double length = 0.0;
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Vector3d p = loop[i], q = loop[(i + 1) % n];
    const double sp = side(p), sq = side(q);
    if (sp < 0.0 && sq < 0.0) continue;
    if (sp < 0.0) p = p + (q - p) * (sp / (sp - sq));
    if (sq < 0.0) q = p + (q - p) * (sp / (sp - sq));
    const double l = (q - p).norm();
    moment += 0.5 * l * (p + q);
    length += l;
  }
  if (!(length > 0.0)) return false;
  centroid = moment / length;
  return true;
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
  SplitPlane plane;
  // T1, T2, T3 as curve integrals (eqs. 14-16 with arc-length measure instead of vertex counts).
  const bool has_top = curve_centroid(upper, [](const Eigen::Vector3d&) { return 1.0; }, plane.T1);
  const bool has_a = curve_centroid(lower, [&](const Eigen::Vector3d& C) { return delta(t, C); }, plane.T2);        // M1
  const bool has_b = curve_centroid(lower, [&](const Eigen::Vector3d& C) { return -delta(1.0 - t, C); }, plane.T3);  // M2
  if (!has_top || !has_a || !has_b) throw EngineError("the sole contour has no points near its toe or heel end");
  return plane_through(plane.T1, plane.T2, plane.T3, side);
}

Eigen::Vector3d curve_mean(const std::vector<Eigen::Vector3d>& loop) {
  Eigen::Vector3d mean;
  if (!curve_centroid(loop, [](const Eigen::Vector3d&) { return 1.0; }, mean))
    throw EngineError("the top contour has no length: cannot find its centre");
  return mean;
}

SplitPlane plane_through(const Eigen::Vector3d& T1, const Eigen::Vector3d& T2, const Eigen::Vector3d& T3, FootSide side) {
  SplitPlane plane;
  plane.T1 = T1;
  plane.T2 = T2;
  plane.T3 = T3;
  // Eqs. 17-19 expand the determinant with rows (T2 - T1) and (T3 - T2): the normal is their cross product.
  const Eigen::Vector3d normal = (T2 - T1).cross(T3 - T2);
  const double length = normal.norm();
  if (length < 1e-6 * (T2 - T3).squaredNorm())
    throw EngineError("the top centre lies on the toe-heel line: cannot place the split plane");
  plane.normal = normal / length;
  if (plane.normal.y() * medial_y_sign(side) < 0.0) plane.normal = -plane.normal;
  plane.offset = -plane.normal.dot(T1);  // eq. 20
  return plane;
}

}  // namespace lastcut
