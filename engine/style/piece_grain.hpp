#pragma once
// A piece's grain line (issue 34, point 3): the direction the leather's backbone or the textile's warp
// must run in the cut piece, given by the style on the last and carried into the piece's flattening.
// The style gives an angle from the last's heel-to-toe axis (the canonical frame's +X); each triangle's
// flattening maps that axis, projected onto the triangle, into the plane, and the area-weighted mean of
// those directions is the piece's axis, turned counter-clockwise by the angle (the flattening keeps
// angles nearly: ARAP is close to conformal where it is close to isometric). On a piece round the heel
// (a counter) the axis runs one way on each side and the directions cancel: where their sum is less
// than half the sum of their lengths, the piece's longest extent is the axis. The line lies in the
// middle of the longest chord of the net outline along that direction (a counter's area centroid lies
// outside it), 60 % of that chord long, at most 120 mm.
#include "engine/core/polygon.hpp"
#include "engine/style/piece_mold.hpp"
#include "engine/style/piece_surface.hpp"

namespace lastcut {

struct GrainLine {
  Point2 from_mm = Point2::Zero(), to_mm = Point2::Zero();  // in the piece's flattening; the arrow points at to_mm
};

// grain_deg: counter-clockwise from the heel-to-toe axis, seen on the piece's grain side.
GrainLine piece_grain_line(const PieceSurface& surface, const PieceMold& mold, double grain_deg);

}  // namespace lastcut
