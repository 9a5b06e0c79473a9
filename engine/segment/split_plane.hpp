#pragma once
// The lengthwise plane that splits a last into its medial and lateral halves (thesis step 3,
// Sabaliauskas 2017, section 3.1, eqs. 14-20).
// A and B are the two lower-contour points furthest apart (toe and heel). The plane gamma(t),
// orthogonal to AB at A(1-t) + Bt, selects M1 = lower-contour points on A's side of gamma(t) and
// M2 = those on B's side of gamma(1-t). The split plane passes through
//   T1 = mean of the upper contour (the centre of the top opening, as the experts draw it),
//   T2 = mean of M1, T3 = mean of M2.
// The means are taken along the curves (arc-length weighted, edges clipped exactly at gamma), not
// over vertices, so the plane does not move when the scan's triangle density changes.
#include <Eigen/Core>
#include <vector>

#include "engine/core/foot_side.hpp"

namespace lastcut {

struct SplitPlane {
  Eigen::Vector3d normal;  // unit, pointing to the medial side
  double offset = 0;       // signed distance of p is normal . p + offset (mm), > 0 on the medial side
  Eigen::Vector3d T1, T2, T3;  // the three points (mm)
};

// lower, upper: smoothed closed contours (mm), canonical frame. t in (0, 1/2), thesis value 1/3.
// Throws EngineError when a part of the lower contour is empty or the three points are collinear.
SplitPlane split_plane(const std::vector<Eigen::Vector3d>& lower, const std::vector<Eigen::Vector3d>& upper, double t,
                       FootSide side);

// Arc-length mean of a closed polyline (mm): T1 when it is the top rim. Throws EngineError when it has no length.
Eigen::Vector3d curve_mean(const std::vector<Eigen::Vector3d>& loop);

// The plane through T1, T2, T3 (mm), normal towards the medial side of `side`, offset so that T1 lies
// on it (eq. 20). Throws EngineError when the points are (nearly) collinear.
SplitPlane plane_through(const Eigen::Vector3d& T1, const Eigen::Vector3d& T2, const Eigen::Vector3d& T3, FootSide side);

}  // namespace lastcut
