#include "engine/toolpath/cut_program.hpp"

namespace lastcut {

std::string to_string(ToolRole role) {
  switch (role) {
    case ToolRole::Cut: return "cut";
    case ToolRole::Mark: return "mark";
    case ToolRole::Pen: return "pen";
  }
  return "cut";
}

double polyline_length(const std::vector<Point2>& points_mm) {
  double length_mm = 0.0;
  for (size_t i = 1; i < points_mm.size(); ++i) length_mm += (points_mm[i] - points_mm[i - 1]).norm();
  return length_mm;
}

CutStats measure_program(const CutProgram& program) {
  CutStats stats;
  Point2 tool_mm = Point2::Zero();
  for (const Stroke& stroke : program.strokes) {
    if (stroke.points_mm.empty()) continue;
    stats.travel_length_mm += (stroke.points_mm.front() - tool_mm).norm();
    const double length_mm = polyline_length(stroke.points_mm);
    if (stroke.tool == ToolRole::Cut) {
      stats.cut_length_mm += length_mm;
    } else {
      stats.mark_length_mm += length_mm;
    }
    tool_mm = stroke.points_mm.back();
    ++stats.tool_lifts;
    ++stats.strokes;
  }
  stats.travel_length_mm += tool_mm.norm();
  return stats;
}

}  // namespace lastcut
