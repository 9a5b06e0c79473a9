#pragma once
// An SVG picture of a layout for the cutting room: the strip or every used hide (outline, defects
// hatched in red, quality zones in orange with their quality), each piece filled with its label
// (or item id) and its pen/notch marks, a title line with utilisation and length or hides, and the
// pieces that could not be placed with their reasons. Units in the file: mm (viewBox), y up.
#include <filesystem>
#include <string>

#include "engine/nest/layout.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut {

std::string layout_svg(const Layout& layout, const NestInstance& instance);
// Throws EngineError when the file cannot be written.
void write_layout_svg(const std::filesystem::path& path, const Layout& layout, const NestInstance& instance);

}  // namespace lastcut
