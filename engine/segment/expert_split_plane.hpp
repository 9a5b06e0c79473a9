#pragma once
// The lengthwise split plane as experts draw it by hand (M. Sabaliauskas, "Computerized modeling
// technology of unique footwear surface manufacturing design", doctoral thesis, Vilnius University,
// 2017): section 2.1, "a point marked in the last which corresponds to the middle line of the
// finger next to big toe. Then a straight line is drawn through this point towards the arithmetic
// average of the last's upper surface and the final drawing goes into the direction of the most
// distant point of the heel"; section 4.1, each last "cut straight from the middle of a heel to the
// middle of the second foot's finger". The last makers' main axis runs the same way, "through the
// center of where the tip of the second toe will lie" (oneandawl.org, "Reference Points and Lines").
//
// The plane passes through three points, each on a contour the halves are cut along:
//   T1 (top centre)  the arc-length mean of the top rim, as in split_plane.hpp;
//   T2 (second toe)  on the feather line's toe end. The toe box is measured across the section
//                    x = x_back + toe_section_fraction (x_front - x_back) of the feather line: its
//                    medial and lateral edges y_m, y_l are the outermost crossings of the line with
//                    that section. The second toe's middle line is y2 = y_m + second_toe_fraction
//                    (y_l - y_m); T2 is the front-most crossing of the feather line with y = y2 ahead
//                    of the section (the point the expert marks at the front of the toe);
//   T3 (heel middle) the middle of the heel's back curve at feather height: the arc of the feather
//                    line whose distance from T2 is within heel_arc_drop_mm of its largest ("the
//                    most distant point of the heel", taken as an arc so that scanner noise on a
//                    round heel cannot slide the point sideways), T3 its point at half the arc's
//                    length. On a heel that is round about the axis this is the farthest point.
// Everything is measured on the curves (edges cut exactly at the sections), not at vertices, so the
// plane does not depend on how densely the contours are sampled.
#include <Eigen/Core>
#include <vector>

#include "engine/core/foot_side.hpp"
#include "engine/segment/split_plane.hpp"

namespace lastcut {

struct ExpertSplitOptions {
  // Where the toe box is measured, as a share of the feather line's length from the heel: the toes'
  // middle on a last of ordinary toe shape (the toe tips lie in the front ~10 %).
  double toe_section_fraction = 0.9;
  // Second toe's middle line, as a share of the toe box width from its medial edge. An estimate from
  // ordinary toe widths (the big toe takes about a quarter of the toe box, the second toe's middle
  // lies a little beyond it); no published measurement for lasts was found. Valid (0, 1).
  double second_toe_fraction = 1.0 / 3.0;
  double heel_arc_drop_mm = 2.0;  // the heel arc: feather points within this of the largest distance from T2
};

// lower, upper: the smoothed feather line and top rim (closed loops, mm, canonical frame: +X heel
// to toe, sole on z = 0). Returns the plane through T1 (top centre), T2 (second toe), T3 (heel
// middle), normal pointing to the medial side of `side`. Throws EngineError (one line) when a
// contour is too short, a section misses the feather line, or the three points are collinear.
SplitPlane expert_split_plane(const std::vector<Eigen::Vector3d>& lower, const std::vector<Eigen::Vector3d>& upper,
                              const ExpertSplitOptions& options, FootSide side);

}  // namespace lastcut
