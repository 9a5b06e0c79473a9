#pragma once
// Notches on a style's pieces (issue 34, point 3), so the closing room can stitch them mark to mark:
//   - balance notches along every sewn curve (a style line, a centre seam), at arc lengths k x spacing
//     from the curve's start for k = 1, 2, ... while k x spacing <= length - spacing / 2 (the rule of the
//     half molds, engine/mold/balance_notches.hpp). A notch is one 3D point of the last; each piece whose
//     outline runs through it gets it, on its net line (the stitch line) where the net's outward normal
//     meets the cut line. The sewn stretches are held at their 3D length (arap_held_lengths.hpp), so the
//     k-th notches of the two sides lie at the same arc length on both pieces;
//   - junction notches where a line crosses a centre seam or ends on another line: on the piece whose
//     outline runs straight through that point (the vamp, at the front seam), not on the pieces that
//     have a corner there (the quarters), which mark it already.
// Balance notches closer than half a spacing to a junction on their curve are left out: two marks a
// few millimetres apart would be taken for one.
#include <Eigen/Core>

#include <string>
#include <vector>

#include "engine/style/piece_mold.hpp"
#include "engine/style/piece_surface.hpp"

namespace lastcut {

// A curve pieces are sewn along, on the new last (canonical frame, mm), in its own direction.
struct SewnCurve {
  PieceEdgeSource source;  // a Line, FrontSeam or BackSeam
  std::string name;        // the line's name ("NAME (2)" for its second run on the upper), "front seam" or "back seam"
  std::vector<Eigen::Vector3d> points_mm;
};

// The style lines' runs and one copy of each centre seam (both halves' seams are one curve).
std::vector<SewnCurve> sewn_curves(const PieceEdgeCurves& curves, const std::vector<std::string>& line_names);

struct NotchPoint {
  std::string name;          // "vamp 2" (the 2nd balance notch along the vamp line), "vamp x front seam"
  Eigen::Vector3d position_mm = Eigen::Vector3d::Zero();
  double arc_length_mm = 0;  // along its curve from the start (balance notches)
  bool balance = true;       // false: a junction notch
};

// Where lines cross a centre seam or end on another line (canonical frame, mm): junction notches,
// each once. lines: transferred (positions in the new scan's frame), named by line_names.
std::vector<NotchPoint> line_junctions(const std::vector<TransferredCurve>& lines, const std::vector<std::string>& line_names,
                                       const Eigen::Affine3d& scan_to_canonical);

// The junctions and the balance notches of every curve (spacing_mm > 0).
std::vector<NotchPoint> seam_notch_points(const std::vector<SewnCurve>& curves, const std::vector<NotchPoint>& junctions,
                                          double spacing_mm);

// A notch as placed on a piece: on its net line (mm, the piece's flattening) and as cut (mold.marks).
struct PieceNotch {
  std::string name;
  Point2 net_point_mm = Point2::Zero();
  double arc_length_mm = 0;
  bool balance = true;
};

// Adds to mold.mold.marks the notches whose points lie on the piece's outline (within kOnPieceOutline_mm
// in 3D) and returns them; `surface` is the piece's 3D surface mold was made from.
inline constexpr double kOnPieceOutline_mm = 0.05;
std::vector<PieceNotch> place_piece_notches(const PieceSurface& surface, const std::vector<NotchPoint>& points, PieceMold& mold);

}  // namespace lastcut
