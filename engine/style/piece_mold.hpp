#pragma once
// A piece's mold: its 3D surface (piece_surface.hpp) flattened on its own with ARAP (the thesis's
// "flattening by the 3D contour") and its outline grown by the allowance each edge needs.
//
// Each stretch of the piece's outline is told by what it lies on in 3D: the feather line (lasting
// margin, folded under the insole), the top edge (folded), a cut stretch of a centre seam, or one of
// the style's lines. The caller's rule turns that into an allowance: shoemaking's defaults are
// lasting 18 mm, folding 5 mm, underlay 8 mm (the piece that lies under its neighbour at a line) and
// butted 0 (a raw or butted edge). The net outline is simplified per stretch (Douglas-Peucker, the
// stretch ends kept) and grown by edge_allowance.hpp.
#include <functional>
#include <string>
#include <vector>

#include "engine/flatten/distortion.hpp"
#include "engine/flatten/flatten.hpp"
#include "engine/mold/mold.hpp"
#include "engine/style/piece_surface.hpp"

namespace lastcut {

// What a stretch of a piece's outline lies on.
struct PieceEdgeSource {
  enum class Kind { Feather, Top, FrontSeam, BackSeam, Line };
  Kind kind = Kind::Feather;
  int line = -1;  // index into the style's lines, for Kind::Line
  bool operator==(const PieceEdgeSource&) const = default;
};

std::string to_string(const PieceEdgeSource& source, const std::vector<std::string>& line_names);

// Sewn to another piece: a style line or a cut stretch of a centre seam (an uncut one is inside a piece).
// The feather line is lasted and the top edge folded: they are sewn to nothing.
bool is_sewn(const PieceEdgeSource& source);

// The 3D curves a piece's outline may lie on, in the new last's canonical frame (mm).
// Each half's outline edges, and each style line as its runs on the upper (runs_on_upper).
struct PieceEdgeCurves {
  std::vector<std::pair<PieceEdgeSource, std::vector<Eigen::Vector3d>>> curves;
};

// The halves' outline edges and the transferred lines (their position_mm in the scan frame, moved by
// scan_to_canonical).
PieceEdgeCurves piece_edge_curves(const std::array<const SegmentResult*, 2>& halves, const std::vector<TransferredCurve>& lines,
                                  const Eigen::Affine3d& scan_to_canonical);

struct PieceMoldEdge {
  PieceEdgeSource source;
  double allowance_mm = 0;
  std::vector<Point2> net_points;  // the stretch of the net outline, mm
  double length_3d_mm = 0;         // the same stretch on the surface flattened (sewn stretches are held to it in 2D)
  std::vector<int> outline_vertices;  // the stretch's vertices of the piece's mesh, corner to corner, CCW in UV
};

struct PieceMold {
  Mold mold;                 // cut outline (CCW) and net; no marks yet
  std::vector<PieceMoldEdge> edges;  // in outline order
  Eigen::MatrixXd UV;        // the piece's flattening, #V x 2 mm
  FlattenResult flatten;
  DistortionMeasures measures;
};

using AllowanceRule = std::function<double(const PieceEdgeSource&)>;

inline constexpr double kPieceSimplifyTolerance_mm = 0.02;

// A top edge's allowance above this is an extension beyond the last (a tongue's top), not a fold (shops
// fold 4-8 mm): it is grown from the edge's outer hull chain (engine/mold/outer_hull_chain.hpp), so the
// tab's top is smooth where the edge kinks inward.
inline constexpr double kTopExtensionAbove_mm = 10;

struct PieceMoldOptions {
  FlattenOptions flatten;
  // Hold the sewn stretches (style lines, cut centre seams) at their 3D length after flattening
  // (arap_held_lengths.hpp), so both pieces of a seam have its length; off: plain ARAP, as the halves.
  bool hold_sewn_lengths = true;
  // Flatten the surface moved this far off the last (mm, piece_thickness.hpp: half the material's
  // thickness, its mid-surface); 0: the last's surface. The stretches are told on the surface as cut.
  double surface_offset_mm = 0;
};

// Throws EngineError (one line, naming the piece) when the piece is not a disk, its offset surface folds or
// its flattening overlaps.
PieceMold make_piece_mold(const PieceSurface& piece, const PieceEdgeCurves& curves, const AllowanceRule& allowance_of,
                          const PieceMoldOptions& options = {});

}  // namespace lastcut
