#pragma once
// The forme of a reference last as shoe CAD shows it (issue 34, point 1): both halves' flattenings laid
// over each other on their common centre line, so a pattern maker draws a style once for both sides.
//
//   lateral: its flattening (SegmentResult::UV) as it is;
//   medial:  its flattening mirrored (v -> -v: the medial and lateral halves are mirror images across the
//            last's centre plane, and each flattening keeps heel left, toe right, so unmirrored their top
//            edges lie on opposite sides), then moved rigidly onto the lateral by the rotation and
//            translation that lay its centre line on the lateral's in the least-squares sense
//            (W. Kabsch, "A solution for the best rotation to relate two sets of vectors", Acta Cryst. A32,
//            1976; in 2D the rotation has a closed form).
// The centre line is the front seam (toe -> top_front) and the back seam (heel -> top_back). Both halves
// share them in 3D, so the points at equal shares of 3D arc length (forme_boundary.hpp) correspond: each
// seam is sampled about once per millimetre of its length, and those pairs are fitted.
//
// Deterministic: a style drawn on the forme is lifted back by recomputing this layout from the same
// reference last (style_folder, forme_lift.hpp).
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "engine/core/polygon.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/forme_boundary.hpp"

namespace lastcut {

struct FormeHalfLayout {
  const SegmentResult* segment = nullptr;  // the reference's half; must outlive the layout
  FormeBoundary boundary;                  // its outline split at its landmarks
  Eigen::MatrixXd forme_uv_mm;             // #V x 2: segment->UV as laid on the forme
  bool mirrored = false;                   // v -> -v before the rotation (the medial half)
  Eigen::Matrix2d rotation = Eigen::Matrix2d::Identity();
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();

  // A point of the half's flattening (SegmentResult::UV, mm) on the forme.
  Point2 to_forme(const Point2& uv_mm) const;
  // The forme points of one outline edge, in the edge's order (forme_boundary.hpp).
  std::vector<Point2> edge_points(EdgeKind kind) const;
  // The whole outline on the forme, in the order of the half's boundary loop.
  std::vector<Point2> outline() const;
  Point2 landmark(const std::string& name) const;
  // An outline edge's length on the last (3D, mm).
  double edge_length_mm(EdgeKind kind) const;
  // The 3D point (canonical frame) at a share of an outline edge's 3D length.
  Eigen::Vector3d edge_point_3d(EdgeKind kind, double share) const;
};

struct FormeLayout {
  std::array<FormeHalfLayout, 2> halves;  // [0] medial, [1] lateral (as half_index in upper_regions.hpp)
  double rotation_deg = 0;                // of the medial's fit, after mirroring
  double centre_rms_mm = 0;               // the medial's centre-line samples to the lateral's, after the fit
  double centre_worst_mm = 0;
  int centre_samples = 0;
};

// reference: a scan_to_molds result with named medial and lateral halves. Throws EngineError (one line)
// when it has none (a symmetric last with no side named) or a half's outline cannot be split at its landmarks.
FormeLayout forme_layout(const ScanResult& reference);

}  // namespace lastcut
