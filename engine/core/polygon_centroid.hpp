#pragma once
// The area centroid of a polygon (where a label sits inside a piece: mold files, layout pictures) and
// its principal axis (which way a piece or a hide is long: alignment starts, a hide's backbone).
#include "engine/core/polygon.hpp"

namespace lastcut {

// Centroid (mm) of the area enclosed by `polygon` (either orientation); the first point when the
// area is zero. Precondition: at least one point.
Point2 area_centroid(const Polygon2& polygon);

// Unit vector along the principal axis of the area enclosed by `polygon` (either orientation): the
// axis of the larger second moment of area about the centroid (Green's theorem over the edges). Its
// sign is arbitrary: an axis, not a direction. Undefined when the area is zero.
Point2 principal_axis(const Polygon2& polygon);

}  // namespace lastcut
