#pragma once
// Style lines made from a mesh's own geometry, and the distance a transferred line is judged by: the
// oracle of the style transfer's tests and benchmark (tests/style, bench/style), independent of the
// transfer itself.
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "engine/core/tri_mesh.hpp"
#include "engine/core/polyline_3d.hpp"

namespace lastcut::test {

using Polyline = std::vector<Eigen::Vector3d>;

// The closed loop where the plane {p : unit_normal . p = offset_mm} cuts the mesh, ordered by angle around
// its centroid (use sections that are star-shaped about it), closed by repeating the first point.
inline Polyline plane_section(const TriMesh& mesh, const Eigen::Vector3d& unit_normal, double offset_mm) {
  Polyline points;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      if (a > b) continue;  // each edge once: on a closed mesh every edge runs both ways
      const double da = unit_normal.dot(mesh.V.row(a).transpose()) - offset_mm;
      const double db = unit_normal.dot(mesh.V.row(b).transpose()) - offset_mm;
      if ((da < 0) == (db < 0)) continue;
      const double t = da / (da - db);
      points.push_back((1 - t) * mesh.V.row(a).transpose() + t * mesh.V.row(b).transpose());
    }
  if (points.empty()) return points;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  const Eigen::Vector3d u = unit_normal.unitOrthogonal(), w = unit_normal.cross(u);
  const auto angle = [&](const Eigen::Vector3d& p) { return std::atan2((p - centroid).dot(w), (p - centroid).dot(u)); };
  std::sort(points.begin(), points.end(), [&](const auto& p, const auto& q) { return angle(p) < angle(q); });
  points.push_back(points.front());
  return points;
}

// The plane through `point_mm` with normal direction `normal` (any length) cut with the mesh.
inline Polyline plane_section_through(const TriMesh& mesh, const Eigen::Vector3d& normal, const Eigen::Vector3d& point_mm) {
  return plane_section(mesh, normal.normalized(), normal.normalized().dot(point_mm));
}

// The longest run of consecutive points of a closed loop (first point repeated last) that satisfy `keep`,
// as an open polyline: a loop cut down to the part of the last a style line belongs to.
template <typename Keep>
Polyline longest_run(const Polyline& loop, Keep keep) {
  const std::size_t n = loop.size() - 1;  // distinct points
  Polyline best, run;
  for (std::size_t i = 0; i < 2 * n; ++i) {  // twice round: a run may wrap past the first point
    if (keep(loop[i % n]) && run.size() < n) {
      run.push_back(loop[i % n]);
      if (run.size() > best.size()) best = run;
    } else {
      run.clear();
    }
  }
  return best;
}

inline double distance_to_polyline(const Eigen::Vector3d& p, const Polyline& line) { return closest_on_polyline(p, line).distance_mm; }

}  // namespace lastcut::test
