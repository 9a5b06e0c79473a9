#include "engine/nest/hide_container.hpp"

#include "engine/nest/clipper_paths.hpp"
#include "engine/nest/overlap_proxy.hpp"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lastcut::nest_detail {
namespace {

using ClipperLib::Path;
using ClipperLib::Paths;

// Offsets one ring by delta_mm (positive grows it); may split into several rings or vanish.
// Round joins are chords of the true arcs, up to the arc tolerance short of them: the offset goes
// that much further, so the result always covers the exact offset (a piece slid up to a grown defect
// must still clear it by the margin).
std::vector<std::vector<Point2>> offset_ring(const std::vector<Point2>& ring, double delta_mm, double scale) {
  if (delta_mm == 0) return {ring};
  const double arc_tolerance_mm = 0.01 * std::abs(delta_mm);
  ClipperLib::ClipperOffset offset(2.0, std::max(1.0, arc_tolerance_mm * scale));
  offset.AddPath(to_path(ring, scale), ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  Paths result;
  offset.Execute(result, (delta_mm + std::copysign(arc_tolerance_mm + 2.0 / scale, delta_mm)) * scale);
  std::vector<std::vector<Point2>> rings;
  for (const Path& r : result) {
    if (ClipperLib::Area(r) <= 0 || r.size() < 3) continue;  // outer parts only
    rings.push_back(from_path(r, scale));
  }
  return rings;
}

}  // namespace

HideContainer::HideContainer(const Bin& bin, double inset_mm, const std::vector<int>& min_qualities) {
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
  // One grid per distinct set of forbidden rings among the qualities in use (keyed by the lowest
  // min_quality giving that set).
  std::vector<int> levels;  // zone qualities, ascending
  for (const QualityZone& zone : bin.zones) levels.push_back(zone.quality);
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  auto key = [&levels](int q) {  // the smallest quality with the same zones below it
    int k = std::numeric_limits<int>::min();
    for (int level : levels)
      if (level < q) k = level + 1;
    return k;
  };
  std::vector<int> keys;
  for (int q : min_qualities) keys.push_back(key(q));
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  for (int k : keys) {
    build_grid(false, k);
    if (k != std::numeric_limits<int>::min()) build_grid(true, k);
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

double HideContainer::DistanceGrid::at(const Point2& p) const {
  const double fx = std::clamp((p.x() - x0) / step - 0.5, 0.0, nx - 1.0), fy = std::clamp((p.y() - y0) / step - 0.5, 0.0, ny - 1.0);
  const int ix = std::min(static_cast<int>(fx), nx - 2 < 0 ? 0 : nx - 2), iy = std::min(static_cast<int>(fy), ny - 2 < 0 ? 0 : ny - 2);
  const int jx = std::min(ix + 1, nx - 1), jy = std::min(iy + 1, ny - 1);
  const double tx = fx - ix, ty = fy - iy;
  auto v = [this](int x, int y) { return static_cast<double>(value[static_cast<size_t>(y) * nx + x]); };
  return (1 - ty) * ((1 - tx) * v(ix, iy) + tx * v(jx, iy)) + ty * ((1 - tx) * v(ix, jy) + tx * v(jx, jy));
}

void HideContainer::build_grid(bool zones_only, int min_quality) {
  DistanceGrid grid;
  grid.zones_only = zones_only;
  grid.min_quality = min_quality;
  constexpr int kCells = 160;
  grid.step = std::max(box_.width(), box_.height()) / kCells;
  if (!(grid.step > 0)) grid.step = 1;
  grid.x0 = box_.x0, grid.y0 = box_.y0;
  grid.nx = std::max(1, static_cast<int>(std::ceil(box_.width() / grid.step)));
  grid.ny = std::max(1, static_cast<int>(std::ceil(box_.height() / grid.step)));
  // Distances beyond kCapCells cells are capped: each edge only updates the cells near it.
  constexpr int kCapCells = 8;
  const double cap = kCapCells * grid.step;
  grid.value.assign(static_cast<size_t>(grid.nx) * grid.ny, static_cast<float>(cap));
  for (const Ring& ring : rings_) {
    if (!relevant(ring, min_quality, zones_only)) continue;
    for (size_t j = 0, m = ring.points.size(); j < m; ++j) {
      const Point2& a = ring.points[j];
      const Point2& b = ring.points[(j + 1) % m];
      const int x_lo = std::max(0, static_cast<int>(std::floor((std::min(a.x(), b.x()) - cap - grid.x0) / grid.step)));
      const int x_hi = std::min(grid.nx - 1, static_cast<int>(std::ceil((std::max(a.x(), b.x()) + cap - grid.x0) / grid.step)));
      const int y_lo = std::max(0, static_cast<int>(std::floor((std::min(a.y(), b.y()) - cap - grid.y0) / grid.step)));
      const int y_hi = std::min(grid.ny - 1, static_cast<int>(std::ceil((std::max(a.y(), b.y()) + cap - grid.y0) / grid.step)));
      for (int y = y_lo; y <= y_hi; ++y)
        for (int x = x_lo; x <= x_hi; ++x) {
          const Point2 c(grid.x0 + (x + 0.5) * grid.step, grid.y0 + (y + 0.5) * grid.step);
          float& v = grid.value[static_cast<size_t>(y) * grid.nx + x];
          v = std::min(v, static_cast<float>(distance_to_segment(c, a, b)));
        }
    }
  }
  for (int y = 0; y < grid.ny; ++y)
    for (int x = 0; x < grid.nx; ++x) {
      const Point2 c(grid.x0 + (x + 0.5) * grid.step, grid.y0 + (y + 0.5) * grid.step);
      if (!usable_point(c, min_quality, zones_only)) grid.value[static_cast<size_t>(y) * grid.nx + x] *= -1;
    }
  grids_.push_back(std::move(grid));
}

const HideContainer::DistanceGrid* HideContainer::grid_for(bool zones_only, int min_quality) const {
  // The grid with the same forbidden rings: the largest min_quality not above the one asked for.
  const DistanceGrid* best = nullptr;
  for (const DistanceGrid& g : grids_)
    if (g.zones_only == zones_only && g.min_quality <= min_quality && (!best || g.min_quality > best->min_quality)) best = &g;
  return best;
}

double HideContainer::pole_penalty(const std::vector<Pole>& poles, const Point2& offset, int min_quality, bool zones_only,
                                   double eps_mm) const {
  const DistanceGrid* grid = grid_for(zones_only, min_quality);
  double total = 0;
  for (const Pole& pole : poles) {
    // Penetration depth of the pole into the forbidden side: r - (signed distance of its centre).
    const double signed_distance = grid ? grid->at(pole.center + offset) : 0.0;
    total += smoothed_depth(pole.radius_mm - signed_distance, eps_mm) * pole.radius_mm;
  }
  return total;
}

double HideContainer::exterior_overlap(const OrientedShape& shape, const Point2& offset, int min_quality,
                                       double eps_mm) const {
  double total = 0;
  // As for two pieces: colliding outlines overlap a little (eps^2) even where no pole reaches out.
  if (collides(shape.outline, shape.box, offset, min_quality, false))
    total += eps_mm * eps_mm + pole_penalty(shape.poles, offset, min_quality, false, eps_mm);
  for (const OrientedRegion& region : shape.regions)
    if (collides(region.outline, region.box, offset, region.min_quality, true))
      total += eps_mm * eps_mm + pole_penalty(region.poles, offset, region.min_quality, true, eps_mm);
  return total;
}

}  // namespace lastcut::nest_detail
