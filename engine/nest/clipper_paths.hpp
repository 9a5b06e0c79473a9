#pragma once
// Rings in mm to and from Clipper's integer paths. scale: integer units per mm, chosen by the caller
// so that the coordinates it handles stay well inside Clipper's range. (The independent checker,
// engine/nest/layout_check, keeps its own conversion on purpose: it shares no code with the nester.)
#include <polyclipping/clipper.hpp>

#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut::nest_detail {

// Each point moved by shift_mm, then scaled and rounded to the nearest integer.
ClipperLib::Path to_path(const std::vector<Point2>& ring, double scale, const Point2& shift_mm = Point2::Zero());
std::vector<Point2> from_path(const ClipperLib::Path& path, double scale);

}  // namespace lastcut::nest_detail
