#include "engine/nest/layout_check.hpp"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace lastcut {
namespace {

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

struct Scaled {
  double scale;
  Path path(const Polygon2& polygon) const {
    Path p;
    for (const Point2& q : polygon.points)
      p.push_back(IntPoint(static_cast<cInt>(std::llround(q.x() * scale)), static_cast<cInt>(std::llround(q.y() * scale))));
    return p;
  }
};

double area(const Paths& paths) {
  double a = 0;
  for (const Path& p : paths) a += ClipperLib::Area(p);
  return std::abs(a);
}

Paths boolean(ClipperLib::ClipType type, const Paths& subject, const Paths& clip) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(subject, ClipperLib::ptSubject, true);
  clipper.AddPaths(clip, ClipperLib::ptClip, true);
  Paths result;
  clipper.Execute(type, result, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return result;
}

Paths grow(const Path& path, double delta) {
  if (delta <= 0) return {path};
  ClipperLib::ClipperOffset offset(2.0, std::max(1.0, delta * 1e-3));
  offset.AddPath(path, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  Paths result;
  offset.Execute(result, delta);
  return result;
}

std::string text(const char* format, double a, double b = 0, double c = 0) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, format, a, b, c);
  return buffer;
}

double axis_deviation_deg(double angle_deg) {
  double a = std::fmod(angle_deg, 180.0);
  if (a > 90.0) a -= 180.0;
  if (a <= -90.0) a += 180.0;
  return a;
}

bool same_angle(double a_deg, double b_deg) {
  double d = std::fmod(std::abs(a_deg - b_deg), 360.0);
  return std::min(d, 360.0 - d) < 1e-6;
}

struct Box {
  double x0, y0, x1, y1;
};
Box box_of(const Polygon2& p) {
  Box b{1e300, 1e300, -1e300, -1e300};
  for (const Point2& q : p.points) b = {std::min(b.x0, q.x()), std::min(b.y0, q.y()), std::max(b.x1, q.x()), std::max(b.y1, q.y())};
  return b;
}

// Area centroid of a simple polygon (the shoelace formula).
Point2 centroid(const Polygon2& polygon) {
  double a = 0, cx = 0, cy = 0;
  for (size_t i = 0, n = polygon.points.size(); i < n; ++i) {
    const Point2& p = polygon.points[i];
    const Point2& q = polygon.points[(i + 1) % n];
    const double cross = p.x() * q.y() - q.x() * p.y();
    a += cross, cx += (p.x() + q.x()) * cross, cy += (p.y() + q.y()) * cross;
  }
  return a != 0 ? Point2(cx / (3 * a), cy / (3 * a)) : polygon.points.front();
}

double diagonal(const NestItem& item) {
  const Box b = box_of(item.shape);
  return std::hypot(b.x1 - b.x0, b.y1 - b.y0);
}

}  // namespace

std::vector<std::string> check_layout(const Layout& layout, const NestInstance& instance, double gap_mm, double margin_mm) {
  std::vector<std::string> problems;
  const double gap = gap_mm >= 0 ? gap_mm : instance.gap_mm;
  const double margin = margin_mm >= 0 ? margin_mm : instance.margin_mm;
  const bool strip = instance.strip_height.has_value();
  // Items by id; counts.
  std::map<int, const NestItem*> items;
  for (const NestItem& item : instance.items) items[item.id] = &item;
  std::map<int, const Bin*> bins;
  for (const Bin& bin : instance.bins) bins[bin.id] = &bin;
  std::map<int, int> placed_count, unplaced_count;
  std::vector<Polygon2> shapes;
  std::vector<const NestItem*> shape_items;
  std::vector<std::pair<int, int>> shape_bins;
  std::vector<size_t> shape_index;  // placement of each shape
  double extent = 1;
  for (size_t k = 0; k < layout.placements.size(); ++k) {
    const Placement& p = layout.placements[k];
    const std::string where = "placement " + std::to_string(k) + " (item " + std::to_string(p.item) + ")";
    auto it = items.find(p.item);
    if (it == items.end()) {
      problems.push_back(where + ": unknown item");
      continue;
    }
    const NestItem& item = *it->second;
    ++placed_count[p.item];
    if (strip && p.bin >= 0) problems.push_back(where + ": names a hide on a strip layout");
    if (!strip && (!bins.count(p.bin) || p.copy < 0 || p.copy >= bins[p.bin]->stock))
      problems.push_back(where + ": unknown hide " + std::to_string(p.bin) + " copy " + std::to_string(p.copy));
    if (!item.allowed_rotations_deg.empty() &&
        std::none_of(item.allowed_rotations_deg.begin(), item.allowed_rotations_deg.end(),
                     [&](double r) { return same_angle(r, p.rotation_deg); }))
      problems.push_back(where + text(": rotation %g deg is not allowed", p.rotation_deg));
    if (p.mirrored && !item.allow_mirror) problems.push_back(where + ": mirrored but mirroring is not allowed");
    if (item.grain_deg) {
      // The material's grain: the hide's backbone when it has one, its x axis otherwise (strips too).
      const double material = !strip && bins.count(p.bin) ? bins[p.bin]->backbone_deg.value_or(0) : 0;
      const double deviation = std::abs(axis_deviation_deg(*placed_grain_deg(item, p) - material));
      if (deviation > item.grain_tolerance_deg + 1e-6)
        problems.push_back(where + text(": grain is %g deg off the material's grain (tolerance %g)", deviation, item.grain_tolerance_deg));
    }
    shapes.push_back(placed_shape(item, p));
    shape_index.push_back(k);
    shape_items.push_back(&item);
    shape_bins.push_back({p.bin, p.copy});
    for (const Point2& q : shapes.back().points) extent = std::max({extent, std::abs(q.x()), std::abs(q.y())});
  }
  for (const Unplaced& u : layout.unplaced) {
    unplaced_count[u.item] += u.count;
    if (u.reason.empty()) problems.push_back("unplaced item " + std::to_string(u.item) + " has no reason");
  }
  for (const NestItem& item : instance.items)
    if (placed_count[item.id] + unplaced_count[item.id] != item.demand)
      problems.push_back("item " + std::to_string(item.id) + ": demand " + std::to_string(item.demand) + " but " +
                         std::to_string(placed_count[item.id]) + " placed and " + std::to_string(unplaced_count[item.id]) + " unplaced");
  if (strip && layout.strip_length) extent = std::max({extent, *layout.strip_length, *instance.strip_height});
  for (const Bin& bin : instance.bins)
    for (const Point2& q : bin.outer.points) extent = std::max({extent, std::abs(q.x()), std::abs(q.y())});
  const Scaled s{1e9 / (extent + gap + margin)};
  // Containment.
  for (size_t k = 0; k < shapes.size(); ++k) {
    const std::string where = "placement " + std::to_string(k) + " (item " + std::to_string(shape_items[k]->id) + ")";
    const double tolerance = 1e-8 * std::abs(ClipperLib::Area(s.path(shapes[k])));
    if (strip) {
      const double length = layout.strip_length.value_or(0);
      const Polygon2 inside{{{margin, margin}, {length - margin, margin}, {length - margin, *instance.strip_height - margin}, {margin, *instance.strip_height - margin}}};
      if (area(boolean(ClipperLib::ctDifference, {s.path(shapes[k])}, {s.path(inside)})) > tolerance)
        problems.push_back(where + ": sticks out of the strip (margin included)");
      continue;
    }
    if (!bins.count(shape_bins[k].first)) continue;
    const Bin& bin = *bins[shape_bins[k].first];
    const Paths grown = grow(s.path(shapes[k]), margin * s.scale);
    if (area(boolean(ClipperLib::ctDifference, grown, {s.path(bin.outer)})) > tolerance)
      problems.push_back(where + ": sticks out of hide " + std::to_string(bin.id) + " (margin included)");
    for (size_t h = 0; h < bin.holes.size(); ++h)
      if (area(boolean(ClipperLib::ctIntersection, grown, {s.path(bin.holes[h])})) > tolerance)
        problems.push_back(where + ": covers defect " + std::to_string(h) + " of hide " + std::to_string(bin.id) + " (margin included)");
    for (size_t z = 0; z < bin.zones.size(); ++z)
      if (bin.zones[z].quality < shape_items[k]->min_quality &&
          area(boolean(ClipperLib::ctIntersection, {s.path(shapes[k])}, {s.path(bin.zones[z].shape)})) > tolerance)
        problems.push_back(where + ": lies on zone " + std::to_string(z) + " of quality " + std::to_string(bin.zones[z].quality) +
                           " but needs " + std::to_string(shape_items[k]->min_quality));
    for (size_t r = 0; r < shape_items[k]->quality_regions.size(); ++r) {
      const QualityRegion& region = shape_items[k]->quality_regions[r];
      Polygon2 placed_region;
      for (const Point2& q : region.shape.points) placed_region.points.push_back(place_point(q, layout.placements[shape_index[k]]));
      const Paths region_path{s.path(placed_region)};
      for (size_t z = 0; z < bin.zones.size(); ++z)
        if (bin.zones[z].quality < region.min_quality &&
            area(boolean(ClipperLib::ctIntersection, region_path, {s.path(bin.zones[z].shape)})) > tolerance)
          problems.push_back(where + ": its quality region " + std::to_string(r) + " lies on zone " + std::to_string(z) +
                             " of quality " + std::to_string(bin.zones[z].quality) + " but needs " + std::to_string(region.min_quality));
    }
  }
  // Pair groups: all pieces of a group placed or none, on one hide, each near another piece of it.
  if (!strip) {
    std::map<std::string, std::vector<size_t>> groups;  // placed shapes per group
    std::map<std::string, int> demanded;
    for (const NestItem& item : instance.items)
      if (!item.pair_group.empty()) demanded[item.pair_group] += item.demand;
    for (size_t k = 0; k < shapes.size(); ++k)
      if (!shape_items[k]->pair_group.empty()) groups[shape_items[k]->pair_group].push_back(k);
    for (const auto& [group, members] : groups) {
      if (static_cast<int>(members.size()) != demanded[group])
        problems.push_back("pair group " + group + ": " + std::to_string(members.size()) + " of its " +
                           std::to_string(demanded[group]) + " pieces placed (all or none)");
      for (size_t a : members) {
        if (shape_bins[a] != shape_bins[members.front()])
          problems.push_back("pair group " + group + ": placement " + std::to_string(shape_index[a]) + " is on another hide");
        bool near = members.size() < 2;
        for (size_t b : members) {
          if (a == b || shape_bins[a] != shape_bins[b]) continue;
          const double bound = instance.pair_distance_mm > 0
                                   ? instance.pair_distance_mm
                                   : 0.5 * (diagonal(*shape_items[a]) + diagonal(*shape_items[b])) + gap;
          near |= (centroid(shapes[a]) - centroid(shapes[b])).norm() <= bound;
        }
        if (!near)
          problems.push_back("pair group " + group + ": placement " + std::to_string(shape_index[a]) +
                             " is not near another piece of its group");
      }
    }
  }
  // Overlaps and gaps, pairwise on pieces grown by gap / 2.
  std::vector<Paths> grown(shapes.size());
  std::vector<Box> boxes(shapes.size());
  for (size_t k = 0; k < shapes.size(); ++k) grown[k] = grow(s.path(shapes[k]), gap / 2 * s.scale), boxes[k] = box_of(shapes[k]);
  for (size_t a = 0; a < shapes.size(); ++a)
    for (size_t b = a + 1; b < shapes.size(); ++b) {
      if (shape_bins[a] != shape_bins[b]) continue;
      if (boxes[a].x0 > boxes[b].x1 + gap || boxes[b].x0 > boxes[a].x1 + gap || boxes[a].y0 > boxes[b].y1 + gap ||
          boxes[b].y0 > boxes[a].y1 + gap)
        continue;
      const double tolerance = 1e-8 * std::min(std::abs(ClipperLib::Area(s.path(shapes[a]))), std::abs(ClipperLib::Area(s.path(shapes[b]))));
      const double common = area(boolean(ClipperLib::ctIntersection, grown[a], grown[b]));
      if (common > tolerance)
        problems.push_back("placements " + std::to_string(a) + " and " + std::to_string(b) +
                           text(gap > 0 ? ": closer than the gap (%.3g mm2 of overlap when grown by gap/2)" : ": overlap (%.3g mm2)",
                                common / (s.scale * s.scale)));
    }
  // Reported figures (only computable when every reference resolves).
  const bool references_resolve = std::all_of(layout.placements.begin(), layout.placements.end(), [&](const Placement& p) {
    return items.count(p.item) && (strip || bins.count(p.bin));
  });
  if (!references_resolve) return problems;
  Layout recomputed = layout;
  update_utilisation(recomputed, instance);
  if (std::abs(recomputed.utilisation - layout.utilisation) > 1e-6)
    problems.push_back(text("utilisation %.6f reported, %.6f recomputed", layout.utilisation, recomputed.utilisation));
  if (strip && !layout.strip_length) problems.push_back("strip layout without strip_length");
  return problems;
}

}  // namespace lastcut
