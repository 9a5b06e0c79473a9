#pragma once
// Where a notch is cut on a mold's outline, and which way it points. Shared by the half molds
// (make_mold.cpp: landmark and balance notches) and a style's pieces (engine/style/piece_notches.hpp).
#include <string>

#include "engine/mold/mold.hpp"

namespace lastcut {

// A notch at the outline point nearest `point` (mm), pointing inward; at a corner of the outline it
// bisects the two edges.
MoldMark notch_at(const std::string& name, const Polygon2& outline, const Point2& point);

// A notch where the net line's outward normal from `net_point` first meets the outline, pointing
// back at net_point, so the notch marks the stitch point even where the allowance changes; the
// nearest outline point when the normal misses (it cannot for a grown outline). outward: unit, mm.
MoldMark notch_along_normal(const std::string& name, const Polygon2& outline, const Point2& net_point, const Point2& outward);

}  // namespace lastcut
