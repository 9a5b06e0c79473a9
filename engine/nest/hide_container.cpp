#include "engine/nest/hide_container.hpp"

#include "engine/nest/clipper_paths.hpp"
#include "engine/nest/overlap_proxy.hpp"

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

bool HideContainer::usable_point(const Point2& p, int min_quality, bool zones_only) const {
  bool in_outer = zones_only;
  for (const Ring& ring : rings_) {
    if (!relevant(ring, min_quality, zones_only) || p.x() < ring.box.x0 || p.x() > ring.box.x1 || p.y() < ring.box.y0 ||
        p.y() > ring.box.y1)
      continue;
    const bool inside = point_in_ring(p, ring.points);
    if (ring.kind == Ring::Outer) in_outer |= inside;
    else if (inside) return false;
  }
  return in_outer;
}

bool HideContainer::collides(const std::vector<Point2>& outline, const Box& box, const Point2& offset, int min_quality,
                             bool zones_only) const {
  const Box world = box.shifted(offset);
  if (!zones_only && !box_.contains(world)) return true;
  if (!usable_point(outline[0] + offset, min_quality, zones_only)) return true;  // cheapest rejection first
  const PlacedRing piece{&outline, box, offset};
  for (const Ring& ring : rings_) {
    if (!relevant(ring, min_quality, zones_only) || !ring.box.overlaps(world)) continue;
    // The piece always lies within the outer ring's box, so rings_collide's containment answer
    // would be wrong for it: for the outer ring only crossing edges count.
    if (ring.kind == Ring::Outer) {
      for (size_t j = 0, m = ring.points.size(); j < m; ++j) {
        const Point2& c = ring.points[j];
        const Point2& d = ring.points[(j + 1) % m];
        if (std::max(c.x(), d.x()) < world.x0 || std::min(c.x(), d.x()) > world.x1 || std::max(c.y(), d.y()) < world.y0 ||
            std::min(c.y(), d.y()) > world.y1)
          continue;
        for (size_t i = 0, n = outline.size(); i < n; ++i)
          if (segments_touch(outline[i] + offset, outline[(i + 1) % n] + offset, c, d)) return true;
      }
    } else if (rings_collide(piece, PlacedRing{&ring.points, ring.box, Point2::Zero()})) {
      return true;
    }
  }
  return false;
}

double HideContainer::pole_penalty(const std::vector<Pole>& poles, const Box& box, const Point2& offset, int min_quality,
                                   bool zones_only, double eps_mm) const {
  // Hazard edges further than `reach` from a pole change its term by little: they are skipped.
  const double reach = std::max(box.width(), box.height());
  const Box near = {box.x0 + offset.x() - reach, box.y0 + offset.y() - reach, box.x1 + offset.x() + reach,
                    box.y1 + offset.y() + reach};
  double total = 0;
  for (const Pole& pole : poles) {
    const Point2 c = pole.center + offset;
    double distance = reach;
    for (const Ring& ring : rings_) {
      if (!relevant(ring, min_quality, zones_only) || !ring.box.overlaps(near)) continue;
      for (size_t j = 0, m = ring.points.size(); j < m; ++j) {
        const Point2& a = ring.points[j];
        const Point2& b = ring.points[(j + 1) % m];
        if (std::min(a.x(), b.x()) > c.x() + distance || std::max(a.x(), b.x()) < c.x() - distance ||
            std::min(a.y(), b.y()) > c.y() + distance || std::max(a.y(), b.y()) < c.y() - distance)
          continue;
        distance = std::min(distance, distance_to_segment(c, a, b));
      }
    }
    // Penetration depth of the pole into the forbidden side: r - d when its centre is usable, r + d otherwise.
    const double depth = usable_point(c, min_quality, zones_only) ? pole.radius_mm - distance : pole.radius_mm + distance;
    total += smoothed_depth(depth, eps_mm) * pole.radius_mm;
  }
  return total;
}

double HideContainer::exterior_overlap(const OrientedShape& shape, const Point2& offset, int min_quality,
                                       double eps_mm) const {
  double total = 0;
  // As for two pieces: colliding outlines overlap a little (eps^2) even where no pole reaches out.
  if (collides(shape.outline, shape.box, offset, min_quality, false))
    total += eps_mm * eps_mm + pole_penalty(shape.poles, shape.box, offset, min_quality, false, eps_mm);
  for (const OrientedRegion& region : shape.regions)
    if (collides(region.outline, region.box, offset, region.min_quality, true))
      total += eps_mm * eps_mm + pole_penalty(region.poles, region.box, offset, region.min_quality, true, eps_mm);
  return total;
}

}  // namespace lastcut::nest_detail
