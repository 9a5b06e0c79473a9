#include "engine/nest/mold_items.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/engine_error.hpp"

namespace lastcut {

std::vector<NestItem> items_from_molds(const std::vector<Mold>& molds, const MoldNestSpec& spec) {
  if (molds.empty()) throw EngineError("no molds to nest");
  if (spec.copies < 1) throw EngineError("at least one copy of every mold is needed");
  std::vector<NestItem> items;
  int id = 0;
  for (const Mold& mold : molds) {
    if (mold.outline.points.size() < 3 || std::abs(signed_area(mold.outline)) <= 0)
      throw EngineError("mold " + mold.name + " has no usable outline");
    for (int twin = 0; twin < (spec.mirrored_twins ? 2 : 1); ++twin) {
      NestItem item;
      item.id = id++;
      item.demand = spec.copies;
      item.allowed_rotations_deg = spec.rotations_deg;
      item.label = spec.label ? spec.label(mold, twin != 0) : mold.name + (twin ? " (other foot)" : "");
      const double sign = twin ? -1.0 : 1.0;
      for (const Point2& p : mold.outline.points) item.shape.points.emplace_back(sign * p.x(), p.y());
      make_counter_clockwise(item.shape);
      for (const MoldMark& m : mold.marks) {
        MoldMark placed = m;
        placed.position_mm.x() *= sign;
        placed.inward_direction.x() *= sign;
        item.marks.push_back({m.name, placed.position_mm, notch_inner_end(placed)});
      }
      if (spec.grain_tolerance_deg) {
        item.grain_deg = 0.0;
        item.grain_tolerance_deg = *spec.grain_tolerance_deg;
      }
      items.push_back(std::move(item));
    }
  }
  return items;
}

NestInstance instance_from_molds(const std::vector<Mold>& molds, const MoldNestSpec& spec, const std::string& name) {
  if (spec.roll_width_mm <= 0) throw EngineError("the roll width must be positive");
  NestInstance instance;
  instance.name = name;
  instance.strip_height = spec.roll_width_mm;
  instance.gap_mm = spec.gap_mm;
  instance.margin_mm = spec.margin_mm;
  instance.items = items_from_molds(molds, spec);
  return instance;
}

}  // namespace lastcut
