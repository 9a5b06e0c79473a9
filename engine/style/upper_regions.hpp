#pragma once
// The regions of a style's pieces on the new last's upper, found in the flattenings of its two halves
// (issue 34, point 3). Each half's outline is split by the transferred style lines; the pieces are
// the parts that hold a piece's label point. A part that reaches a centre seam continues on the
// other half where no style line crosses the seam between them: a vamp or a counter spans both halves.
//
// In each half's flattening (SegmentResult::UV), with Clipper (Angus Johnson's Clipper 6.4,
// libpolyclipping): every run of a line on that half becomes a strip 2 x kStripHalfWidth_mm wide
// (lengthened past the outline where the line ends on it), and the strips are subtracted from the
// half's outline. What is left falls apart into the regions. Across a seam, two regions belong together
// when points just inside both halves at the same share of the seam lie in them. A seam sample near
// a line's crossing is skipped, so it cannot join the regions on the two sides of that line.
#include <Eigen/Core>
#include <polyclipping/clipper.hpp>

#include <array>
#include <string>
#include <vector>

#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/style_transfer.hpp"

namespace lastcut {

// Half-width of the cut a style line makes in the flattening (mm). The strip's area is left out of
// every piece: about 4e-3 mm^2 per mm of line, far below the 0.1 % that issue 34 lets the pieces miss.
inline constexpr double kStripHalfWidth_mm = 0.002;

struct HalfRegion {
  int half = 0;             // 0: medial, 1: lateral
  ClipperLib::Paths rings;  // the outer ring (counter-clockwise) and its holes, kClipperUnitsPerMm in the half's UV
};

struct PieceRegion {
  std::string name;
  std::vector<HalfRegion> parts;  // one per half it lies on, or more where a half is split between its parts
  // The seam samples at which its parts on the two halves were found to meet: where it is sewn across.
  struct SeamJoin {
    EdgeKind seam = EdgeKind::BackSeam;
    double share = 0;  // of the seam's length from its first landmark (forme_boundary.hpp)
  };
  std::vector<SeamJoin> joins;
};

// A stretch of a centre seam the pieces are cut apart along (a derby's lacing opening, the quarters'
// back seam), between two shares of the seam (forme_boundary.hpp: the front seam runs from the toe up
// to top_front, the back seam from the heel up to top_back). Elsewhere the seams join the halves.
struct SeamCut {
  EdgeKind seam = EdgeKind::BackSeam;
  double from_share = 0, to_share = 1;
};

struct PieceLabel {
  std::string name;
  TransferredPoint point;  // a point inside the piece on the new last (transfer_point of the reference's)
};

// halves: the new last's medial and lateral SegmentResult (in that order); lines: the transferred style
// lines; labels: one per piece. Throws EngineError (one line) when a region holds no label ("a region
// near X has no piece: a label is missing or a line does not reach an edge") or two labels ("pieces A
// and B lie in one region: a style line between them is missing or does not reach an edge").
// labelled_only: a region without a label is left out instead (a partial layer, style_definition.hpp).
std::vector<PieceRegion> piece_regions(const std::array<const SegmentResult*, 2>& halves,
                                       const std::vector<TransferredCurve>& lines, const std::vector<PieceLabel>& labels,
                                       const std::vector<SeamCut>& seam_cuts = {}, bool labelled_only = false);

// 0 for "medial", 1 for "lateral"; throws EngineError otherwise.
int half_index(const std::string& half_name);

}  // namespace lastcut
