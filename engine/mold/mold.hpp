#pragma once
// Mold: the 2D pattern piece cut from leather, made from one flattened half of a last.
//
// make_mold turns a flattened triangle patch (UV, F) into a cutting outline:
//   1. the boundary loop of F is walked in UV (a disk-shaped patch has exactly one loop; more
//      than one loop means holes in the scan, and the longest loop is the outline),
//   2. the loop is made counter-clockwise and checked to be simple (a self-overlapping
//      flattening cannot be cut: EngineError),
//   3. it is simplified within simplify_tolerance_mm by Douglas-Peucker (Douglas & Peucker 1973,
//      "Algorithms for the reduction of the number of points required to represent a digitized
//      line", Cartographica 10(2)); spans whose chord would cross another chord are refined again
//      until the result is simple, so simplification never introduces a self-intersection,
//   4. an optional outward allowance is added: either one distance all around (a Clipper offset
//      with round joins, Clipper 6.4 by Angus Johnson, arc tolerance = simplify tolerance) or one
//      per edge between the landmarks (lasting margin, seam allowance, top line; edge_allowance.hpp),
//      the simplified outline is kept as the mold's net line (the last's edge),
//   5. every landmark vertex becomes a notch mark on the final outline: the nearest outline point
//      (its perpendicular projection) and the inward normal there. Landmark vertices are always
//      kept by the simplification, so without allowance the notch sits exactly on the landmark,
//   6. optional balance notches along the centre cut and the feather line (balance_notches.hpp),
//      placed on the net line and projected onto the outline the same way.
#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/mesh_topology.hpp"
#include "engine/core/polygon.hpp"
#include "engine/mold/balance_notches.hpp"
#include "engine/mold/edge_allowance.hpp"

namespace lastcut {

// A notch at the outline: a short cut perpendicular to the edge, used to line pieces up when
// lasting and stitching. position_mm lies on the outline; inward_direction is a unit vector.
struct MoldMark {
  std::string name;
  Point2 position_mm = Point2::Zero();
  Point2 inward_direction = Point2::Zero();
};

// outline: counter-clockwise, simple, mm; marks: notches on it. net: the last's edge inside the
// allowance (where the leather is folded or stitched), drawn but never cut; empty when the mold
// has no allowance (the outline is the net line).
struct Mold {
  std::string name;
  Polygon2 outline;
  std::vector<MoldMark> marks;
  Polygon2 net;
};

struct MoldOptions {
  double simplify_tolerance_mm = 0.02;  // max distance of a dropped boundary vertex from the outline
  double allowance_mm = 0.0;            // outward margin added all around (>= 0), without landmarks
  // Per-edge allowances instead of allowance_mm (which must then be 0); need the landmarks
  // toe, heel, top_back, top_front on the outline.
  std::optional<EdgeAllowances> edge_allowances;
  BalanceNotches balance_notches;       // off by default; needs the same landmarks
};

// Length of a notch line as drawn in DXF and SVG and cut by the mark tool (mm).
inline constexpr double kNotchLength_mm = 2.0;

// The inner end of a notch line: kNotchLength_mm from the outline along the inward direction.
inline Point2 notch_inner_end(const MoldMark& mark) { return mark.position_mm + kNotchLength_mm * mark.inward_direction; }

// UV #V x 2 flattened positions (mm), F #F x 3 triangles of a disk-shaped patch,
// landmark_vertices: name -> vertex index, normally on the boundary (an interior landmark is
// projected to the nearest outline point).
// Throws EngineError when there is no boundary, the outline overlaps itself or options are bad.
Mold make_mold(std::string name, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F,
               const std::map<std::string, int>& landmark_vertices, const MoldOptions& options = {});
// The same with the patch's topology already built (build_mesh_topology(F, UV.rows())).
Mold make_mold(std::string name, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F,
               const std::map<std::string, int>& landmark_vertices, const MoldOptions& options,
               const MeshTopology& topology);

}  // namespace lastcut
