#pragma once
// Where a piece whose parts lie on both halves of the last is sewn shut across a centre seam (issue 34;
// the layers of style_definition.hpp): its two halves' outline points are one vertex only there.
// piece_regions (upper_regions.hpp) joined the piece's parts where seam samples on both halves fell in
// them (PieceRegion::joins); a point is welded when it lies on the seam near such a sample and not on a
// stretch the style cuts (SeamCut). Without this a quarter lining, which runs round the heel and meets
// itself at the lacing opening and at the back seam above the counter, would be welded shut at the
// point where the vamp line crosses the front seam: a pinched ring, not a piece.
#include <array>
#include <vector>

#include "engine/core/polyline_3d.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/upper_regions.hpp"

namespace lastcut {

// A point is on a seam within this (mm): the seam's points as a piece's cut computes them, on either half.
inline constexpr double kOnSeam_mm = 0.1;
// A joined seam sample welds the seam this far on either side (3D arc length, mm): past the samples'
// spacing and the gap piece_regions leaves at a line's crossing, so a piece is sewn up to the crossing.
inline constexpr double kJoinReach_mm = 3.5;
// A cut stretch begins this far past the crossing of the line it starts at (mm): the crossing itself is
// where a piece sewn below it is still one.
inline constexpr double kCutStart_mm = 0.5;

class SeamWelds {
 public:
  // halves: the new last's medial and lateral halves; piece: its joins; cuts: the seam cuts piece_regions was given.
  SeamWelds(const std::array<const SegmentResult*, 2>& halves, const PieceRegion& piece, const std::vector<SeamCut>& cuts);
  // True when p (the halves' 3D frame), a point on its half's outline, may be one with the other half's.
  bool weldable(const Eigen::Vector3d& p) const;

 private:
  struct Seam {
    EdgeKind kind;
    Polyline3 points;  // one half's seam, from its first landmark
    double length_mm = 0;
  };
  std::vector<Seam> seams_;  // both halves' front and back seams
  std::vector<PieceRegion::SeamJoin> joins_;
  std::vector<SeamCut> cuts_;
};

}  // namespace lastcut
