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
//   4. an optional outward allowance (lasting or seam margin) is added by a Clipper offset with
//      round joins (Clipper 6.4, Angus Johnson), arc tolerance = simplify tolerance,
//   5. every landmark vertex becomes a notch mark on the final outline: the nearest outline point
//      and the inward normal there. Landmark vertices are always kept by the simplification, so
//      without allowance the notch sits exactly on the landmark.
#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "engine/core/mesh_topology.hpp"
#include "engine/core/polygon.hpp"

namespace lastcut {

// A notch at the outline: a short cut perpendicular to the edge, used to line pieces up when
// lasting and stitching. position_mm lies on the outline; inward_direction is a unit vector.
struct MoldMark {
  std::string name;
  Point2 position_mm = Point2::Zero();
  Point2 inward_direction = Point2::Zero();
};

// outline: counter-clockwise, simple, mm; marks: notches on it.
struct Mold {
  std::string name;
  Polygon2 outline;
  std::vector<MoldMark> marks;
};

struct MoldOptions {
  double simplify_tolerance_mm = 0.02;  // max distance of a dropped boundary vertex from the outline
  double allowance_mm = 0.0;            // outward margin added all around (>= 0)
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
