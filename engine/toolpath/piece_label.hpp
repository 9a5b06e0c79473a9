#pragma once
// The short text drawn on each piece so the operator can sort the cut pieces: its place in the
// cutting order, the size and L/R taken from the item label ("42 L medial" -> "3 42 L"), or the
// whole label when its writer made it ready to draw ("#4711 EU44 L med" -> "3 #4711 EU44 L med").
// The text is placed where it fits: the box of the text must lie inside the outline with a
// clearance; candidate centres are grid points ranked by their distance to the outline (the
// roomiest first), and the letter height shrinks from height_mm down to min_height_mm.
#include <optional>
#include <string>
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

// "order label" when item_label starts with '#' (the daemon's labels: order or scan, size, foot,
// half). Otherwise "order size side": size is the first word of item_label holding a digit (its
// digits and decimal point), side is L or R when a word of the label is L/R/LEFT/RIGHT (any case).
std::string piece_marking(int order, const std::string& item_label);

struct PlacedText {
  Point2 center_mm = Point2::Zero();
  double height_mm = 0.0;
};

// Where `text` fits inside `outline` (CCW, mm), or nullopt when it does not fit even at min_height_mm.
std::optional<PlacedText> place_text(const std::string& text, const Polygon2& outline, double height_mm,
                                     double min_height_mm);

}  // namespace lastcut
