#pragma once
// Balance notches: notches along the mold edges that line the pieces up when lasting and
// stitching. Along the centre cut the medial and lateral molds are sewn together, so their
// notches sit at the same arc lengths on the NET line (the stitch line), measured from the toe on
// the front seam and from the heel on the back seam; the two halves of a last have seams of
// (nearly) the same length, so the k-th notches of both pieces meet when sewn. Along the feather
// line they are spaced from the heel, for the laster to check the upper is pulled on evenly.
// The notch is cut where the net line's outward normal at that point meets the cut outline, so the
// notch line points at the stitch point (make_mold). A notch is placed at k * spacing for k = 1, 2, ... while k * spacing <= length - spacing / 2:
// none closer than half a spacing to the landmark notch at the far end.
#include <string>
#include <vector>

#include "engine/mold/edge_allowance.hpp"

namespace lastcut {

// Spacing along the net line in mm; 0 = no balance notches on that edge.
struct BalanceNotches {
  double seam_spacing_mm = 0.0;     // front and back centre cut
  double feather_spacing_mm = 0.0;  // feather line
};

// Smallest spacing accepted (mm): closer notches would weaken the edge and blur together.
inline constexpr double kMinBalanceSpacing_mm = 5.0;

struct NetNotch {
  std::string name;                    // "balance_seam_front_1", "balance_seam_back_2", "balance_feather_3"
  Point2 position_mm = Point2::Zero(); // on the net line
  double arc_length_mm = 0.0;          // from the toe (front seam) or the heel (back seam, feather line)
  Point2 outward_normal = Point2::Zero();  // unit, of the net line there (away from the mold)
};

// edges: from split_net_edges. Throws EngineError when a spacing is neither 0 nor a finite
// number >= kMinBalanceSpacing_mm.
std::vector<NetNotch> balance_notch_points(const std::vector<NetEdge>& edges, const BalanceNotches& spacing);

// The point at arc length s_mm along the open polyline (clamped to its ends) and the unit
// direction of the polyline there.
struct PolylinePoint {
  Point2 point = Point2::Zero();
  Point2 direction = Point2::Zero();
};
PolylinePoint point_at_arc_length(const std::vector<Point2>& polyline, double s_mm);

}  // namespace lastcut
