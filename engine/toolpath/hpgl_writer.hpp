#pragma once
// HPGL (HP-GL/1, as read by pen plotters and leather/vinyl cutters): IN; then per tool SP<n>;
// and VS<cm/s>; travel with PU x,y; tool-down paths with PD x,y,...; absolute coordinates (PA)
// in plotter units (profile.hpgl.units_per_mm, HP's 40 per mm = 0.025 mm). Every command is on its
// own line; long PD runs are split into several commands of at most max_points_per_command pairs
// and max_line_length characters so cutters with small input buffers never overflow.
// Knife angles are not written: HPGL cutters with tangential heads turn the knife themselves.
#include <string>
#include <vector>

#include "engine/toolpath/cut_program.hpp"
#include "engine/toolpath/machine_profile.hpp"

namespace lastcut {

// `stroke_offsets`, when given, gets one entry per stroke of program.strokes, the byte of the text
// where that stroke's commands begin (a skipped stroke: where the next one would), and one more:
// where the last stroke's commands end (the program's closing commands follow).
std::string write_hpgl(const CutProgram& program, const MachineProfile& profile,
                        std::vector<std::size_t>* stroke_offsets);
inline std::string write_hpgl(const CutProgram& program, const MachineProfile& profile) {
  return write_hpgl(program, profile, nullptr);
}

}  // namespace lastcut
