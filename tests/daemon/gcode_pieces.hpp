#pragma once
// An independent reading of a G-code cut file (the grbl tables' files, docs/cut-files.md) for the
// tests: the pieces it cuts, each with its label from the "; piece k/n: LABEL (item i)" comment and
// the path the knife follows while it is down (Z below 0), arcs (G2/G3 with I, J) sampled every 2
// degrees. It knows nothing of the planner or the nester: the tests judge what the knife would do.
#include <string>
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut::daemon::testing {

struct CutPiece {
  std::string label;                // as written in the comment ("" when the piece has none)
  int item = -1;                    // the layout's item id
  std::vector<Point2> knife_path_mm;  // the knife's path while down, in order, table coordinates
};

std::vector<CutPiece> pieces_of_gcode(const std::string& gcode);

// The knife's path as a closed ring (the overcut past the start is cut off): the polygon the piece is.
Polygon2 cut_outline(const CutPiece& piece);

// The direction (degrees in [0, 180)) of the ring's principal axis: the longer axis of its second
// moments of area. A grain line's direction is this plus a fixed angle of the piece's own.
double principal_axis_deg(const Polygon2& ring);

}  // namespace lastcut::daemon::testing
