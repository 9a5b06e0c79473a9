#pragma once
// The outer hull chain of an open polyline: the part of its convex hull's boundary that runs from its
// first point to its last on the outward side, that is, the polyline with every dent on that side
// bridged by a straight line. For a top edge cut as an extension beyond the last (a tongue's top, 25 mm
// above the top edge): the allowance grown from this chain gives a smooth tab, where the exact offset
// of the edge kept each of its kinks as a notch (the last's top edge kinks at the front centre).
// Andrew's monotone chain ("Another efficient algorithm for convex hulls in two dimensions", Information
// Processing Letters 9, 1979), in the frame of the chord from the first point to the last.
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

// points: >= 2 (mm), in outline order of a counter-clockwise outline, so that outward is to the right
// of travel. Returns the chain from points.front() to points.back(); the points as they are when an end
// is not the extreme point along the chord (the chain would not start or end there) or there are fewer
// than 3.
std::vector<Point2> outer_hull_chain(const std::vector<Point2>& points);

}  // namespace lastcut
