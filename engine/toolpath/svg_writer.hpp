#pragma once
// SVG preview of a cut program, true size in mm with +Y up like the machine: the work area,
// outlines (black), marks (red), labels (blue), tool-up travel (dashed grey) in cutting order and
// a green dot where each contour cut starts. For the operator to check a job before sending it.
#include <string>

#include "engine/toolpath/cut_program.hpp"

namespace lastcut {

std::string write_svg(const CutProgram& program);

}  // namespace lastcut
