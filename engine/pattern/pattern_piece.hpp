#pragma once
// PatternPiece: one pattern piece as pattern CAD and cutting rooms exchange it (DXF-AAMA,
// engine/pattern/aama_dxf.hpp): the closed cut line, the lines drawn on the piece but not cut,
// notches, the grain line, and the piece's labels. Plain data in millimetres.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

struct PatternNotch {
  Point2 at_mm;                  // on the cut line
  Point2 inward = Point2(0, 1);  // unit vector into the piece
};

struct PatternPiece {
  std::string name;        // Piece Name
  std::string style;       // Style Name
  std::string size;        // Size label, e.g. "42"
  std::string category;    // Category: the material, e.g. "upper leather"
  std::string annotation;  // free text, e.g. "right" (the foot)
  int quantity = 1;        // Quantity
  std::vector<Point2> cut_line_mm;  // closed, counter-clockwise, first point not repeated
  // Lines drawn on the piece, not cut. A closed line (the net line) repeats its first point at its end.
  std::vector<std::vector<Point2>> internal_lines_mm;  // layer 8: drawn, not cut (e.g. the net line)
  std::vector<std::vector<Point2>> sew_lines_mm;       // layer 14: drawn, not cut
  std::vector<PatternNotch> notches;                   // layer 4
  std::optional<std::array<Point2, 2>> grain_line_mm;  // layer 7: from, to (arrow direction)
};

}  // namespace lastcut
