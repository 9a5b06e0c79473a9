#pragma once
// Open 3D polylines (mm): length, the closest point to a point, the point at an arc length. Style lines,
// centre seams and the stretches of a piece's outline are such polylines (engine/style).
#include <Eigen/Core>

#include <vector>

namespace lastcut {

using Polyline3 = std::vector<Eigen::Vector3d>;

double polyline_length_mm(const Polyline3& polyline);

struct PolylineHit {
  double distance_mm = 0;    // from the point to the polyline
  double arc_length_mm = 0;  // of the closest point, from the polyline's start
  Eigen::Vector3d point_mm = Eigen::Vector3d::Zero();
};

// polyline: >= 1 point.
PolylineHit closest_on_polyline(const Eigen::Vector3d& p, const Polyline3& polyline);

// The point at arc length s_mm from the start, clamped to the ends; polyline >= 1 point.
Eigen::Vector3d point_at_arc_length(const Polyline3& polyline, double s_mm);

}  // namespace lastcut
