#pragma once
// Comparing two molds of the same half: rigid alignment (rotation + translation, never a
// mirror) and the symmetric Hausdorff distance between outlines. Used to check that two scans of
// one last give the same molds.
//   Start: the least-squares rigid map between marks of the same name (Kabsch / Umeyama,
//   "Least-squares estimation of transformation parameters between two point patterns",
//   IEEE PAMI 13(4), 1991, without scale); with fewer than two shared marks, centroids and
//   principal axes (both proper orientations are tried).
//   Refinement: ICP (Besl & McKay, "A method for registration of 3-D shapes", IEEE PAMI 14(2),
//   1992) from points sampled along the moving outline to their closest points on the fixed one.
#include <vector>

#include "engine/mold/mold.hpp"

namespace lastcut {

struct RigidTransform2 {
  Eigen::Matrix2d rotation = Eigen::Matrix2d::Identity();  // det = +1
  Point2 translation = Point2::Zero();                      // mm
  Point2 apply(const Point2& p) const { return rotation * p + translation; }
};

// Least-squares rigid map (no reflection, no scale) taking from[i] to to[i]; sizes equal, >= 2.
RigidTransform2 fit_rigid(const std::vector<Point2>& from, const std::vector<Point2>& to);

Polygon2 transformed(const Polygon2& polygon, const RigidTransform2& transform);

// Points every step_mm along the closed outline (its vertices included).
std::vector<Point2> sample_outline(const Polygon2& polygon, double step_mm);

// Rigid transform that puts `moving` onto `fixed` (see above).
RigidTransform2 align_molds(const Mold& moving, const Mold& fixed);

// Symmetric Hausdorff distance (mm) between two closed outlines, sampled every step_mm.
double hausdorff_distance_mm(const Polygon2& a, const Polygon2& b, double step_mm = 0.25);

}  // namespace lastcut
