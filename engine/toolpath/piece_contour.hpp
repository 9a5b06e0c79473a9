#pragma once
// The contour cut of one piece: where it starts and how it closes.
//
// Start: a blade entering the leather leaves a small mark, so the cut starts at a corner, where
// that mark disappears in the corner, rather than in the middle of a smooth edge that stays
// visible on the finished shoe. The start is the sharpest convex corner whose turn exceeds
// corner_min_deg; a piece without such a corner starts at its vertex nearest to `preferred_mm`
// (the tool's position, to save travel).
// Close: the knife runs on past the start point for overcut_mm along the first edges, so the
// piece comes free even when the blade lifts a little early.
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

// Index of the start vertex of `outline` (counter-clockwise, >= 3 points).
int contour_start_vertex(const Polygon2& outline, const Point2& preferred_mm, double corner_min_deg);

// The closed cut path: outline from start_vertex around back to it, then overcut_mm further.
// Returns #P x 2 points (mm), first = outline[start_vertex].
std::vector<Point2> contour_cut_path(const Polygon2& outline, int start_vertex, double overcut_mm);

// True when the outline has a convex corner sharper than corner_min_deg (then the start is fixed).
bool has_start_corner(const Polygon2& outline, double corner_min_deg);

}  // namespace lastcut
