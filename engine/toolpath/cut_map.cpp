// make_cut_map (cut_map.hpp): the byte span of each piece from the writer's stroke offsets.
#include "engine/toolpath/cut_map.hpp"

#include <algorithm>
#include <cmath>

namespace lastcut {

CutMap make_cut_map(const CutFile& file) {
  CutMap map;
  map.bytes_total = file.text.size();
  map.table_x_mm = file.program.work_area_x_mm;
  map.table_y_mm = file.program.work_area_y_mm;
  const auto& strokes = file.program.strokes;
  if (file.stroke_offsets.size() != strokes.size() + 1) return map;
  for (const ProgramPiece& piece : file.program.pieces) map.pieces.push_back({piece.label, piece.marking, map.bytes_total, 0, piece.outline_mm});
  for (std::size_t s = 0; s < strokes.size(); ++s) {
    const int piece = strokes[s].piece;
    if (piece < 0 || static_cast<std::size_t>(piece) >= map.pieces.size()) continue;
    const std::size_t end = file.stroke_offsets[s + 1];
    CutMapPiece& span = map.pieces[static_cast<std::size_t>(piece)];
    span.first_byte = std::min(span.first_byte, file.stroke_offsets[s]);
    span.end_byte = std::max(span.end_byte, end);
  }
  for (CutMapPiece& span : map.pieces)
    if (span.end_byte == 0) span.first_byte = 0;  // a piece without strokes: nothing of the file cuts it
  return map;
}

nlohmann::json to_json(const CutMap& map) {
  const auto tenth = [](double value) { return std::round(value * 10.0) / 10.0; };
  nlohmann::json pieces = nlohmann::json::array();
  for (const CutMapPiece& piece : map.pieces) {
    nlohmann::json outline = nlohmann::json::array();
    for (const Point2& point : piece.outline_mm.points) outline.push_back({tenth(point.x()), tenth(point.y())});
    pieces.push_back({{"label", piece.label}, {"marking", piece.marking}, {"first_byte", piece.first_byte},
                      {"end_byte", piece.end_byte}, {"outline_mm", outline}});
  }
  return {{"bytes_total", map.bytes_total}, {"table_mm", {map.table_x_mm, map.table_y_mm}}, {"pieces", pieces}};
}

}  // namespace lastcut
