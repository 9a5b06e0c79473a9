#pragma once
// "The two shoes of a pair go on one hide, preferably mirrored about the backbone" (issue 35). A hide
// is close to symmetric about its backbone: thickness, stretch and the tightness of the grain change
// alike on both sides of it. So a shoe's piece and the other foot's copy of it (the same piece
// mirrored, NestItem::mirror_key) match best when they are cut at mirror places of the hide.
//
// After the nesting, each such pair on a hide with a backbone is tried at mirror poses: first the
// second piece on the mirror image of the first one's pose, then the other way round. A move is kept
// when the hide still passes the independent checker (layout_check.hpp, on that hide alone: inside,
// margins, gaps, zones, grain, rotations). Otherwise both pieces stay where the nester put them. The
// pieces placed, the hides used and the utilisation never change.
//
// The mirror of a pose. A piece is placed as w = R(theta) p + t. Its twin is q = S p + d, where
// S: (x, y) -> (-x, y) in the own frame and d is the offset between their frames. The backbone is the
// line through c at angle beta, and its reflection is F = R(2 beta) diag(1, -1). Since
// F R(theta) S = R(2 beta - theta - 180 deg), the mirror image F (w - c) + c of the placed piece is the
// twin placed with
//   rotation  2 beta - theta - 180 deg
//   offset    c + F (t - c) - R(rotation) d.
// The line is the one the hide file drew (Bin::backbone_point), else the one through the outline's
// centroid.
#include "engine/nest/layout.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut {

struct MirroredPairs {
  int pairs = 0;     // a piece and its other foot's copy on one hide that has a backbone
  int mirrored = 0;  // of them, at mirror poses (within 0.01 mm and 0.01 deg)
};

// The pairs of `layout` and how many lie mirrored; nothing changes.
MirroredPairs count_mirrored_pairs(const Layout& layout, const NestInstance& instance);

// Moves pieces onto mirror poses of their other foot's copy where the hide allows (see above) and
// returns the count afterwards. gap/margin as check_layout (the instance's when negative).
MirroredPairs mirror_pairs_about_backbone(Layout& layout, const NestInstance& instance, double gap_mm = -1,
                                          double margin_mm = -1);

// The twin's placement mirroring `from` (placed as `from_pose`) about `hide`'s backbone; the hide
// must have one. Exposed for the tests.
Placement mirrored_pose(const NestItem& from, const Placement& from_pose, const NestItem& twin, const Bin& hide);

}  // namespace lastcut
