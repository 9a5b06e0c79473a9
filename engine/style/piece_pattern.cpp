// A style's piece as a pattern piece; see piece_pattern.hpp.
#include "engine/style/piece_pattern.hpp"

namespace lastcut {

PatternPiece pattern_piece(const StylePieceResult& piece, const std::string& style, const std::string& size, const std::string& foot) {
  PatternPiece pattern;
  pattern.name = piece.spec.name;
  pattern.style = style;
  pattern.size = size;
  pattern.category = piece.spec.material;
  pattern.annotation = foot;
  pattern.quantity = piece.spec.quantity;
  const Mold& mold = piece.mold.mold;
  pattern.cut_line_mm = mold.outline.points;
  if (!mold.net.points.empty()) {
    std::vector<Point2> net = mold.net.points;
    net.push_back(net.front());
    pattern.internal_lines_mm.push_back(std::move(net));
  }
  for (const PieceMoldEdge& edge : piece.mold.edges)
    if (is_sewn(edge.source) && edge.net_points.size() >= 2) pattern.sew_lines_mm.push_back(edge.net_points);
  for (const MoldMark& mark : mold.marks) pattern.notches.push_back({mark.position_mm, mark.inward_direction});
  if ((piece.grain.to_mm - piece.grain.from_mm).norm() > 0) pattern.grain_line_mm = std::array<Point2, 2>{piece.grain.from_mm, piece.grain.to_mm};
  return pattern;
}

}  // namespace lastcut
