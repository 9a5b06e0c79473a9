#pragma once
// A first estimate of how long the machine needs for a program: tool-down length at each tool's
// speed plus tool-up travel at the travel speed. Acceleration, plunges and lifts are not counted,
// so real machines take longer; the estimate is for comparing jobs and planning the shift.
#include "engine/toolpath/cut_program.hpp"
#include "engine/toolpath/machine_profile.hpp"

namespace lastcut {

double estimated_duration_s(const CutProgram& program, const MachineProfile& profile);

}  // namespace lastcut
