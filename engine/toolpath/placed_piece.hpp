#pragma once
// PlacedPiece: one piece where the layout put it, in table coordinates (mm). The toolpath planner
// works on these, so it does not depend on how the layout was made.
#include <string>
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

// A notch or landmark line, table coordinates (mm).
struct PlacedMark {
  std::string name;
  Point2 from_mm = Point2::Zero();
  Point2 to_mm = Point2::Zero();
};

struct PlacedPiece {
  int item_id = -1;
  std::string label;                // the item's label ("42 L medial"), may be empty
  Polygon2 outline;                 // counter-clockwise, simple, >= 3 points, mm
  std::vector<PlacedMark> marks;
  std::vector<std::vector<Point2>> drawn_lines_mm;  // pen lines on the piece, never cut; >= 2 points each
};

}  // namespace lastcut
