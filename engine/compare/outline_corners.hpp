#pragma once
// Corner points of a mold and of a reference pattern, and the thesis's "margins": the distance
// between corresponding corners (heel, toe and the two ends of the top line; M. Sabaliauskas' thesis, Vilnius 2017,
// section 4.1, Figure 9, where 8-9 mm were measured against 2 mm permissible).
//
// The rule, in the mold's frame after the reference has been moved onto it
// (rigid_overlap_alignment):
//   mold corner       the mold's notch mark of that name (lastcut molds carry heel, toe,
//                     top_front, top_back on the outline).
//   reference corner  its notch mark of the same name when it has one (an earlier lastcut mold);
//                     otherwise the sharp corner of its outline nearest to the mold's corner within
//                     search_radius_mm. A sharp corner is a local maximum of the turning angle
//                     |angle between p(s) - p(s - w) and p(s + w) - p(s)| along the outline resampled
//                     every sample_step_mm, w = window_mm, that reaches min_turn_deg; a run of equal
//                     maxima (a rounded corner: an offset copy) counts once, at its middle. The
//                     window of a few mm sees a corner rounded off by a 1 mm offset as one corner
//                     at the middle of its arc, and ignores tracing noise below a few tenths of a mm.
//                     With no sharp corner in reach the closest outline point is used and the
//                     match says so (found_sharp_corner = false).
// The margin is |mold corner - reference corner| (mm).
#include <string>
#include <vector>

#include "engine/mold/mold.hpp"

namespace lastcut {

struct CornerOptions {
  double window_mm = 3.0;
  double min_turn_deg = 30.0;
  double search_radius_mm = 20.0;
  double sample_step_mm = 0.05;
};

struct SharpCorner {
  Point2 at_mm = Point2::Zero();
  double turn_deg = 0.0;  // signed: + convex on a counter-clockwise outline
};

struct CornerMatch {
  std::string name;
  Point2 mold_mm = Point2::Zero();
  Point2 reference_mm = Point2::Zero();
  double margin_mm = 0.0;
  bool from_reference_mark = false;   // the reference carried a notch of this name
  bool found_sharp_corner = true;     // false: nearest outline point used (see above)
};

// Sharp corners of a closed outline (mm, #P >= 3), in outline order.
std::vector<SharpCorner> sharp_corners(const Polygon2& outline, const CornerOptions& options = {});

// One match per mark of `mold`, in the mold's mark order. `reference` is already in the mold's
// frame (outline and marks moved). Empty when the mold has no marks.
std::vector<CornerMatch> match_corners(const Mold& mold, const Mold& reference, const CornerOptions& options = {});

}  // namespace lastcut
