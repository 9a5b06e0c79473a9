#pragma once
// A small single-stroke font for labelling pieces with a pen or a pen-like tool: digits,
// upper-case letters and - + . / : ( ) = _ ? . Glyphs are designed for lastcut on a grid 6 units
// wide and 9 units tall (the cap height), advance 8 units; lower case is drawn as upper case and
// every other character as '?'. Single-stroke means every glyph is a few open polylines the pen
// draws once, with no outlines to fill.
#include <string>
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

// Width of `text` set at cap height height_mm (mm).
double text_width_mm(const std::string& text, double height_mm);

// The strokes drawing `text` with its bounding box centred on center_mm, cap height height_mm,
// reading along +X. Each stroke is an open polyline (mm) with >= 2 points.
std::vector<std::vector<Point2>> text_strokes(const std::string& text, const Point2& center_mm, double height_mm);

}  // namespace lastcut
