#include "engine/nest/layout.hpp"

#include <cmath>
#include <numbers>
#include <set>
#include <utility>

#include "engine/core/engine_error.hpp"

namespace lastcut {

Point2 place_point(const Point2& own, const Placement& placement) {
  const double angle_rad = placement.rotation_deg * std::numbers::pi / 180.0;
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  const double x = placement.mirrored ? -own.x() : own.x();
  const double y = own.y();
  return {c * x - s * y + placement.x, s * x + c * y + placement.y};
}

Polygon2 placed_shape(const NestItem& item, const Placement& placement) {
  Polygon2 placed;
  placed.points.reserve(item.shape.points.size());
  for (const Point2& p : item.shape.points) placed.points.push_back(place_point(p, placement));
  make_counter_clockwise(placed);  // mirroring reverses the orientation
  return placed;
}

std::optional<double> placed_grain_deg(const NestItem& item, const Placement& placement) {
  if (!item.grain_deg) return std::nullopt;
  const double own = placement.mirrored ? 180.0 - *item.grain_deg : *item.grain_deg;
  return own + placement.rotation_deg;
}

const NestItem& find_item(const NestInstance& instance, int item_id) {
  for (const NestItem& item : instance.items)
    if (item.id == item_id) return item;
  throw EngineError("layout refers to item " + std::to_string(item_id) + ", which the instance does not have");
}

std::string unplaced_text(const Unplaced& unplaced, const NestInstance& instance) {
  const std::string& label = find_item(instance, unplaced.item).label;
  const std::string item = "item " + std::to_string(unplaced.item);
  return (label.empty() ? item : label + " (" + item + ")") + " x" + std::to_string(unplaced.count) + ": " + unplaced.reason;
}

const Bin& find_bin(const NestInstance& instance, int bin_id) {
  for (const Bin& bin : instance.bins)
    if (bin.id == bin_id) return bin;
  throw EngineError("layout refers to hide/sheet " + std::to_string(bin_id) + ", which the instance does not have");
}

static double bin_area(const Bin& bin) {
  double area = std::abs(signed_area(bin.outer));
  for (const Polygon2& hole : bin.holes) area -= std::abs(signed_area(hole));
  return area;
}

double used_material_area(const Layout& layout, const NestInstance& instance) {
  if (instance.strip_height) return *instance.strip_height * layout.strip_length.value_or(0.0);
  std::set<std::pair<int, int>> used;
  for (const Placement& p : layout.placements) used.insert({p.bin, p.copy});
  double area = 0;
  for (const auto& [bin_id, copy] : used) area += bin_area(find_bin(instance, bin_id));
  return area;
}

double placed_item_area(const Layout& layout, const NestInstance& instance) {
  double area = 0;
  for (const Placement& p : layout.placements) area += std::abs(signed_area(find_item(instance, p.item).shape));
  return area;
}

int used_bin_count(const Layout& layout) {
  std::set<std::pair<int, int>> used;
  for (const Placement& p : layout.placements)
    if (p.bin >= 0) used.insert({p.bin, p.copy});
  return static_cast<int>(used.size());
}

void update_utilisation(Layout& layout, const NestInstance& instance) {
  const double material = used_material_area(layout, instance);
  layout.utilisation = material > 0 ? placed_item_area(layout, instance) / material : 0.0;
}

}  // namespace lastcut
