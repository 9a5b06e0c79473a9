#include "engine/toolpath/cut_time.hpp"

namespace lastcut {

double estimated_duration_s(const CutProgram& program, const MachineProfile& profile) {
  double seconds = 0.0;
  for (const Stroke& stroke : program.strokes) {
    seconds += polyline_length(stroke.points_mm) / profile.tool(stroke.tool).speed_mm_s;
  }
  return seconds + measure_program(program).travel_length_mm / profile.travel_speed_mm_s;
}

}  // namespace lastcut
