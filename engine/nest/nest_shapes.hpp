#pragma once
// Pieces as the nester sees them: for every allowed pose (rotation, mirror) a CONSERVATIVE
// collision outline (the piece grown by half the gap plus the simplification error, so that
// outlines apart means pieces at least `gap` apart) and a set of poles, the inscribed circles
// that quantify how deeply two overlapping pieces penetrate (the overlap proxy of sparrow:
// Gardeyn, Vanden Berghe & Wauters, arXiv:2509.13329, 2025, after the poles of inaccessibility
// of jagua-rs).
#include <optional>
#include <string>
#include <vector>

#include "engine/nest/nest_geometry.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut::nest_detail {

struct Pose {
  double rotation_deg = 0;  // counter-clockwise about the item's own origin
  bool mirrored = false;    // x -> -x before the rotation
};

struct Pole {
  Point2 center = Point2::Zero();  // mm
  double radius_mm = 0;
};

// The poles again as single-precision lanes, padded with empty poles (radius 0, far away) to a
// multiple of 4, so the overlap measure can take four at a time. Floats suffice: the measure only
// steers the search; collisions are decided exactly on the outlines.
struct PoleLanes {
  std::vector<float> x, y, radius;  // mm
};

// A part of the item that needs better leather (NestItem::quality_regions) in one pose: its
// conservative outline (contains the region) and poles, for the hide container's zone test.
struct OrientedRegion {
  std::vector<Point2> outline;  // counter-clockwise, mm
  Box box;
  std::vector<Pole> poles;
  int min_quality = 0;
};

// The item in one pose, before translation.
struct OrientedShape {
  Pose pose;
  std::vector<Point2> outline;  // conservative collision outline #P, counter-clockwise, mm
  Box box;                      // of the outline
  std::vector<Pole> poles;
  PoleLanes pole_lanes;  // the same poles, for pair_overlap
  std::vector<OrientedRegion> regions;  // only regions stricter than the item's min_quality (hides)
};

struct PreparedItem {
  int item_index = 0;       // into NestInstance::items
  double area_mm2 = 0;      // of the exact shape
  double diameter_mm = 0;   // of the outline's bounding box
  int min_quality = 0;
  std::vector<OrientedShape> orientations;  // empty: no allowed pose (see no_pose_reason)
  std::string no_pose_reason;
  std::vector<Point2> own_outline;  // the conservative outline in the item's own frame
  std::vector<Pole> own_poles;      // its poles, own frame
};

// The poses the item may take: its rotation list (or free rotation in free_step_deg steps),
// with and without mirroring, restricted to those that put the grain within tolerance of the x axis.
std::vector<Pose> allowed_poses(const NestItem& item, double free_step_deg);

// Outline containing `shape` grown by grow_mm, with at most about max_points points
// (Clipper offset, then Douglas-Peucker on the grown outline; the grown distance covers the
// simplification error, and the result is verified to contain the grown shape).
std::vector<Point2> conservative_outline(const Polygon2& shape, double grow_mm, int max_points);

// Up to max_poles disjoint inscribed circles, largest first, of a counter-clockwise ring.
std::vector<Pole> compute_poles(const std::vector<Point2>& ring, int max_poles);

// Everything above for one item. grow_mm = gap / 2. same_shape: an item prepared before from the
// same shape and grow_mm (only its poses may differ, e.g. its grain): its outline and poles are reused.
PreparedItem prepare_item(const NestItem& item, int item_index, double grow_mm, double free_step_deg,
                          const PreparedItem* same_shape = nullptr);

// The poles as lanes (see PoleLanes).
PoleLanes pole_lanes(const std::vector<Pole>& poles);

// An angle in [0, 360) deg (values within 1e-9 of 360 become 0).
double normalise_deg(double deg);

// The pose applied to a point of the own frame (no translation).
Point2 apply_pose(const Point2& point, const Pose& pose);

}  // namespace lastcut::nest_detail
