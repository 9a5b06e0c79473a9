#pragma once
// G-code for grbl (and grbl-compatible controllers such as grblHAL with a rotary axis):
//   G21 (mm), G90 (absolute), G94 (feed per minute); travel with G0; tool down by a Z move
//   (G1 Z.. F plunge) or by the tool's own line (M3/M5, M8/M9, ...); cutting with G1 X Y F
//   (feeds in mm/min); optional rotary axis word (A or C) carrying the tangential knife's
//   unwrapped angle in degrees (a pure "G1 A.." turns the knife in place); optional G2/G3 arcs
//   (I, J relative to the arc start) fitted within profile.gcode.arc_tolerance_mm.
// The program ends at the origin with every tool up, and M2.
#include <string>
#include <vector>

#include "engine/toolpath/cut_program.hpp"
#include "engine/toolpath/machine_profile.hpp"

namespace lastcut {

// `stroke_offsets`, when given, gets one entry per stroke of program.strokes, the byte of the text
// where that stroke's commands begin (a skipped stroke: where the next one would), and one more:
// where the last stroke's commands end (the program's closing commands follow).
std::string write_gcode(const CutProgram& program, const MachineProfile& profile,
                        std::vector<std::size_t>* stroke_offsets);
inline std::string write_gcode(const CutProgram& program, const MachineProfile& profile) {
  return write_gcode(program, profile, nullptr);
}

}  // namespace lastcut
