#include "engine/toolpath/svg_writer.hpp"

#include <algorithm>
#include <sstream>

#include "engine/core/svg_document.hpp"

namespace lastcut {
namespace {

std::string path_data(const std::vector<Point2>& points_mm, bool closed) {
  std::string data;
  for (size_t i = 0; i < points_mm.size(); ++i) {
    data += (i == 0 ? "M" : " L") + svg_number_mm(points_mm[i].x()) + "," + svg_number_mm(points_mm[i].y());
  }
  return closed ? data + " Z" : data;
}

}  // namespace

std::string write_svg(const CutProgram& program) {
  Point2 low = Point2::Zero(), high(program.work_area_x_mm, program.work_area_y_mm);
  for (const Stroke& stroke : program.strokes) {
    for (const Point2& point : stroke.points_mm) {
      low = low.cwiseMin(point);
      high = high.cwiseMax(point);
    }
  }
  const double margin_mm = 5.0;
  const double width_mm = high.x() - low.x() + 2 * margin_mm;
  const double height_mm = high.y() - low.y() + 2 * margin_mm;
  std::ostringstream svg;
  svg << svg_document_start({low.x() - margin_mm, -high.y() - margin_mm, width_mm, height_mm})
      << "<title>lastcut cut program: " << program.pieces.size() << " pieces</title>\n"
      << "<g transform=\"scale(1,-1)\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
  svg << "<rect x=\"0\" y=\"0\" width=\"" << svg_number_mm(program.work_area_x_mm) << "\" height=\""
      << svg_number_mm(program.work_area_y_mm) << "\" stroke=\"#bbbbbb\" stroke-width=\"0.5\"/>\n";
  svg << "<g id=\"travel\" stroke=\"#999999\" stroke-width=\"0.3\" stroke-dasharray=\"2,2\">\n";
  Point2 tool_mm = Point2::Zero();
  for (const Stroke& stroke : program.tip_strokes) {
    svg << "<path d=\"" << path_data({tool_mm, stroke.points_mm.front()}, false) << "\"/>\n";
    tool_mm = stroke.points_mm.back();
  }
  svg << "<path d=\"" << path_data({tool_mm, Point2::Zero()}, false) << "\"/>\n</g>\n";
  svg << "<g id=\"cut\" stroke=\"#000000\" stroke-width=\"0.4\">\n";
  for (size_t i = 0; i < program.pieces.size(); ++i) {
    const ProgramPiece& piece = program.pieces[i];
    svg << "<path d=\"" << path_data(piece.outline_mm.points, true) << "\"><title>" << i + 1 << ": item "
        << piece.item_id << " " << xml_escaped(piece.label) << "</title></path>\n";
  }
  svg << "</g>\n<g id=\"mark\" stroke=\"#d00000\" stroke-width=\"0.4\">\n";
  for (const Stroke& stroke : program.tip_strokes) {
    if (stroke.tool == ToolRole::Mark) svg << "<path d=\"" << path_data(stroke.points_mm, false) << "\"/>\n";
  }
  svg << "</g>\n<g id=\"text\" stroke=\"#0040c0\" stroke-width=\"0.3\">\n";
  for (const Stroke& stroke : program.tip_strokes) {
    if (stroke.tool == ToolRole::Pen) svg << "<path d=\"" << path_data(stroke.points_mm, false) << "\"/>\n";
  }
  svg << "</g>\n<g id=\"start\" fill=\"#00a000\" stroke=\"none\">\n";
  for (const ProgramPiece& piece : program.pieces) {
    const Point2& start = piece.outline_mm.points.front();
    svg << "<circle cx=\"" << svg_number_mm(start.x()) << "\" cy=\"" << svg_number_mm(start.y()) << "\" r=\"1\"/>\n";
  }
  svg << "</g>\n</g>\n" << kSvgDocumentEnd;
  return svg.str();
}

}  // namespace lastcut
