#include "engine/toolpath/dxf_writer.hpp"

#include "engine/core/dxf_document.hpp"

namespace lastcut {

std::string write_dxf(const CutProgram& program) {
  // Layer colours (ACI): CUT white/black, MARK red, TEXT blue.
  DxfDocument dxf(DxfVersion::R2000, {{"0", 7}, {"CUT", 7}, {"MARK", 1}, {"TEXT", 5}});
  dxf.include_in_extents(Point2::Zero());
  dxf.include_in_extents(Point2(program.work_area_x_mm, program.work_area_y_mm));
  for (const ProgramPiece& piece : program.pieces) dxf.polyline("CUT", piece.outline_mm.points, true);
  for (const Stroke& stroke : program.tip_strokes) {
    if (stroke.tool == ToolRole::Mark && stroke.points_mm.size() == 2) {
      dxf.line("MARK", stroke.points_mm[0], stroke.points_mm[1]);
    } else if (stroke.tool == ToolRole::Mark) {
      dxf.polyline("MARK", stroke.points_mm, false);
    } else if (stroke.tool == ToolRole::Pen) {
      dxf.polyline("TEXT", stroke.points_mm, false);
    }
  }
  return dxf.str();
}

}  // namespace lastcut
