#include "engine/toolpath/layout_pieces.hpp"

#include <cmath>

#include "engine/core/engine_error.hpp"
#include "engine/nest/nest_json.hpp"

namespace lastcut {

std::vector<SheetRef> sheets_in_layout(const Layout& layout) {
  std::vector<SheetRef> sheets;
  for (const Placement& placement : layout.placements) {
    const SheetRef sheet{placement.bin, placement.copy};
    bool seen = false;
    for (const SheetRef& known : sheets) seen = seen || known == sheet;
    if (!seen) sheets.push_back(sheet);
  }
  return sheets;
}

std::vector<PlacedPiece> placed_pieces(const Layout& layout, const NestInstance& instance, const SheetRef& sheet) {
  std::vector<PlacedPiece> pieces;
  for (size_t i = 0; i < layout.placements.size(); ++i) {
    const Placement& placement = layout.placements[i];
    if (!(SheetRef{placement.bin, placement.copy} == sheet)) continue;
    if (!std::isfinite(placement.x) || !std::isfinite(placement.y) || !std::isfinite(placement.rotation_deg)) {
      throw EngineError("layout placement " + std::to_string(i + 1) + " (item " + std::to_string(placement.item) +
                        ") has a position or rotation that is not a number");
    }
    const NestItem& item = find_item(instance, placement.item);
    PlacedPiece piece;
    piece.item_id = item.id;
    piece.label = item.label;
    piece.outline = placed_shape(item, placement);
    for (const ItemMark& mark : item.marks) {
      piece.marks.push_back(PlacedMark{mark.name, place_point(mark.from_mm, placement), place_point(mark.to_mm, placement)});
    }
    for (const std::vector<Point2>& line : item.drawn_lines_mm) {
      piece.drawn_lines_mm.emplace_back();
      for (const Point2& point : line) piece.drawn_lines_mm.back().push_back(place_point(point, placement));
    }
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

LayoutFile read_layout_file(const std::filesystem::path& path) {
  const nlohmann::json json = read_json_file(path);
  LayoutFile file;
  file.layout = layout_from_json(json);
  file.instance = instance_from_layout_json(json);
  return file;
}

}  // namespace lastcut
