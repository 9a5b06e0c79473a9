#include "engine/nest/mold_items.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/engine_error.hpp"
#include "engine/nest/clipper_paths.hpp"
#include "engine/nest/nest_geometry.hpp"

#include <polyclipping/clipper.hpp>

namespace lastcut {

std::optional<QualityRegion> toe_region(const NestItem& item, double fraction, int min_quality) {
  auto mark = [&](const std::string& name) -> const ItemMark* {
    for (const ItemMark& m : item.marks)
      if (m.name == name) return &m;
    return nullptr;
  };
  const ItemMark* toe = mark("toe");
  const ItemMark* heel = mark("heel");
  if (!toe || !heel) return std::nullopt;
  const Point2 axis = toe->from_mm - heel->from_mm;  // heel to toe
  const double length = axis.norm();
  if (length <= 0) return std::nullopt;
  const Point2 u = axis / length, v(-u.y(), u.x());
  const nest_detail::Box box = nest_detail::bounding_box(item.shape.points);
  const double reach = 2 * (std::hypot(box.width(), box.height()) + length);
  // The half plane "within fraction x length of the toe" as a large rectangle beyond the toe.
  const Point2 cut = toe->from_mm - fraction * length * u;
  const std::vector<Point2> keep = {cut - reach * v, cut + reach * u - reach * v, cut + reach * u + reach * v, cut + reach * v};
  double extent = 1;
  for (const Point2& p : keep) extent = std::max({extent, std::abs(p.x()), std::abs(p.y())});
  const double scale = 1e9 / extent;
  ClipperLib::Clipper clipper;
  clipper.AddPath(nest_detail::to_path(item.shape.points, scale), ClipperLib::ptSubject, true);
  clipper.AddPath(nest_detail::to_path(keep, scale), ClipperLib::ptClip, true);
  ClipperLib::Paths parts;
  clipper.Execute(ClipperLib::ctIntersection, parts, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  const ClipperLib::Path* largest = nullptr;
  for (const ClipperLib::Path& part : parts)
    if (!largest || std::abs(ClipperLib::Area(part)) > std::abs(ClipperLib::Area(*largest))) largest = &part;
  if (!largest || largest->size() < 3) return std::nullopt;
  QualityRegion region;
  region.shape.points = nest_detail::from_path(*largest, scale);
  make_counter_clockwise(region.shape);
  region.min_quality = min_quality;
  return region;
}

std::vector<NestItem> items_from_molds(const std::vector<Mold>& molds, const MoldNestSpec& spec) {
  if (molds.empty()) throw EngineError("no molds to nest");
  if (spec.copies < 1) throw EngineError("at least one copy of every mold is needed");
  if (spec.toe_region_min_quality > 0 && !(spec.toe_region_fraction > 0 && spec.toe_region_fraction <= 1))
    throw EngineError("the toe region fraction must be in (0, 1] of the mold length");
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
      if (spec.toe_region_min_quality > 0)
        if (auto region = toe_region(item, spec.toe_region_fraction, spec.toe_region_min_quality))
          item.quality_regions.push_back(std::move(*region));
      // The two feet's copies of one piece (the first item of this name and index is its key).
      if (spec.mirrored_twins) item.mirror_key = std::to_string(items.size() - static_cast<std::size_t>(twin)) + " " + mold.name;
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
