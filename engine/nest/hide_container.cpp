#include "engine/nest/hide_container.hpp"

#include "engine/nest/clipper_paths.hpp"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>

namespace lastcut::nest_detail {
namespace {

using ClipperLib::Path;
using ClipperLib::Paths;

// Offsets one ring by delta_mm (positive grows it); may split into several rings or vanish.
std::vector<std::vector<Point2>> offset_ring(const std::vector<Point2>& ring, double delta_mm, double scale) {
  if (delta_mm == 0) return {ring};
  ClipperLib::ClipperOffset offset(2.0, std::max(1.0, 0.01 * std::abs(delta_mm) * scale));
  offset.AddPath(to_path(ring, scale), ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  Paths result;
  offset.Execute(result, delta_mm * scale);
  std::vector<std::vector<Point2>> rings;
  for (const Path& r : result) {
    if (ClipperLib::Area(r) <= 0 || r.size() < 3) continue;  // outer parts only
    rings.push_back(from_path(r, scale));
  }
  return rings;
}

}  // namespace

HideContainer::HideContainer(const Bin& bin, double inset_mm) {
  double extent = 1;
  for (const Point2& p : bin.outer.points) extent = std::max({extent, std::abs(p.x()), std::abs(p.y())});
  const double scale = 1e9 / (extent + std::abs(inset_mm));
  const double inset = std::max(0.0, inset_mm);  // a negative inset is already covered by the grown outlines
  for (auto& r : offset_ring(bin.outer.points, -inset, scale)) rings_.push_back({std::move(r), {}, Ring::Outer, 0});
  for (const Polygon2& hole : bin.holes)
    for (auto& r : offset_ring(hole.points, inset, scale)) rings_.push_back({std::move(r), {}, Ring::Hole, 0});
  for (const QualityZone& zone : bin.zones) rings_.push_back({zone.shape.points, {}, Ring::Zone, zone.quality});
  box_ = bounding_box(bin.outer.points);
  for (Ring& ring : rings_) {
    ring.box = bounding_box(ring.points);
    const double area = std::abs(signed_area(Polygon2{ring.points}));
    if (ring.kind == Ring::Outer) usable_area_mm2_ += area;
    if (ring.kind == Ring::Hole) usable_area_mm2_ -= area;
  }
}

Box HideContainer::offset_range(const OrientedShape& s) const {
  return {box_.x0 - s.box.x0, box_.y0 - s.box.y0, box_.x1 - s.box.x1, box_.y1 - s.box.y1};
}

bool HideContainer::usable_point(const Point2& p, int min_quality) const {
  bool in_outer = false;
  for (const Ring& ring : rings_) {
    if (!relevant(ring, min_quality) || p.x() < ring.box.x0 || p.x() > ring.box.x1 || p.y() < ring.box.y0 || p.y() > ring.box.y1)
      continue;
    const bool inside = point_in_ring(p, ring.points);
    if (ring.kind == Ring::Outer) in_outer |= inside;
    else if (inside) return false;
  }
  return in_outer;
}

bool HideContainer::collides(const OrientedShape& shape, const Point2& offset, int min_quality) const {
  const Box world = shape.box.shifted(offset);
  if (!box_.contains(world)) return true;
  if (!usable_point(shape.outline[0] + offset, min_quality)) return true;  // cheapest rejection first
  const PlacedRing piece{&shape.outline, shape.box, offset};
  for (const Ring& ring : rings_) {
    if (!relevant(ring, min_quality) || !ring.box.overlaps(world)) continue;
    // The piece always lies within the outer ring's box, so rings_collide's containment answer
    // would be wrong for it: for the outer ring only crossing edges count.
    if (ring.kind == Ring::Outer) {
      for (size_t j = 0, m = ring.points.size(); j < m; ++j) {
        const Point2& c = ring.points[j];
        const Point2& d = ring.points[(j + 1) % m];
        if (std::max(c.x(), d.x()) < world.x0 || std::min(c.x(), d.x()) > world.x1 || std::max(c.y(), d.y()) < world.y0 ||
            std::min(c.y(), d.y()) > world.y1)
          continue;
        for (size_t i = 0, n = shape.outline.size(); i < n; ++i)
          if (segments_touch(shape.outline[i] + offset, shape.outline[(i + 1) % n] + offset, c, d)) return true;
      }
    } else if (rings_collide(piece, PlacedRing{&ring.points, ring.box, Point2::Zero()})) {
      return true;
    }
  }
  return false;
}

double HideContainer::exterior_overlap(const OrientedShape& shape, const Point2& offset, int min_quality,
                                       double eps_mm) const {
  if (!collides(shape, offset, min_quality)) return 0;
  // Penalty: eps plus the radius of every pole whose centre is not usable.
  double total = eps_mm * eps_mm;
  for (const Pole& pole : shape.poles)
    if (!usable_point(pole.center + offset, min_quality)) total += pole.radius_mm * pole.radius_mm;
  return total;
}

}  // namespace lastcut::nest_detail
