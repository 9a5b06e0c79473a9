#pragma once
// The area centroid of a polygon: where a label sits inside a piece (mold files, layout pictures).
#include "engine/core/polygon.hpp"

namespace lastcut {

// Centroid (mm) of the area enclosed by `polygon` (either orientation); the first point when the
// area is zero. Precondition: at least one point.
Point2 area_centroid(const Polygon2& polygon);

}  // namespace lastcut
