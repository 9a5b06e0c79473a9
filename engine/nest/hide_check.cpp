// The plausibility checks of a hide read from a file (hide_file.hpp): the rings must be simple,
// holes and zones must lie inside the outline, and the area must be that of a hide.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <polyclipping/clipper.hpp>

#include "engine/core/engine_error.hpp"
#include "engine/core/near_edge_pairs.hpp"
#include "engine/core/segment_predicates.hpp"
#include "engine/nest/clipper_paths.hpp"
#include "engine/nest/hide_file.hpp"

namespace lastcut {
namespace {

// True when two edges that are not neighbours along the ring meet; the ring's points are finite.
bool self_intersects(const Polygon2& ring) {
  const auto& p = ring.points;
  const int n = static_cast<int>(p.size());
  return for_each_near_edge_pair(n, [&](int k) { return p[static_cast<size_t>(k)]; }, 0.0, [&](int i, int j) {
           return !segments_touch(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]);
         }) != EdgePairScan::Completed;
}

// Area (mm^2) of `ring` outside `outer`, by Clipper on a 1 um grid.
double area_outside_mm2(const Polygon2& ring, const Polygon2& outer) {
  constexpr double kScale = 1000.0;  // integer units per mm
  ClipperLib::Clipper clipper;
  clipper.AddPath(nest_detail::to_path(ring.points, kScale), ClipperLib::ptSubject, true);
  clipper.AddPath(nest_detail::to_path(outer.points, kScale), ClipperLib::ptClip, true);
  ClipperLib::Paths outside;
  clipper.Execute(ClipperLib::ctDifference, outside, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  double area = 0;
  for (const auto& path : outside) area += std::abs(ClipperLib::Area(path));
  return area / (kScale * kScale);
}

// No point of a hide drawing lies this far from the drawing's origin (a cutting table is a few metres);
// beyond it Clipper's integer grid would overflow (its exception escaped the hide intake: found by
// tests/fuzz/hide_dxf_fuzz.cpp).
constexpr double kFarthestPoint_mm = 1e7;  // 10 km

void check_ring(const Polygon2& ring, const std::string& source, const std::string& what) {
  if (ring.points.size() < 3) throw EngineError(source + ": the " + what + " has fewer than 3 points");
  for (const Point2& p : ring.points) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) throw EngineError(source + ": the " + what + " has a non-finite point");
    if (std::abs(p.x()) > kFarthestPoint_mm || std::abs(p.y()) > kFarthestPoint_mm)
      throw EngineError(source + ": the " + what + " has a point more than 10 km from the drawing's origin; check the drawing's units");
  }
  // Before the area: a figure eight crosses itself and may enclose no signed area at all.
  if (self_intersects(ring))
    throw EngineError(source + ": the " + what + " crosses itself; redraw it as one simple closed line");
  if (std::abs(signed_area(ring)) <= 0.0) throw EngineError(source + ": the " + what + " has no area");
}

constexpr double kMostlyOutside = 0.1;  // share of a hole's or zone's area

void check_inside(const Polygon2& ring, const Polygon2& outer, const std::string& source, const std::string& what) {
  // Clipper rounds to 1 um: a ring drawn on the outline may stick out by rounding only.
  // A zone or cut-out drawn a little over the edge is harmless (there is no leather beyond it):
  // refused only when more than kMostlyOutside of it lies outside (wrong place, wrong units).
  const double outside_mm2 = area_outside_mm2(ring, outer);
  if (outside_mm2 > std::max(1.0, kMostlyOutside * std::abs(signed_area(ring))))
    throw EngineError(source + ": the " + what + " reaches outside the hide outline (" +
                      std::to_string(static_cast<long>(std::lround(outside_mm2))) + " mm^2 outside)");
}

}  // namespace

void check_hide(const Bin& bin, const std::string& source) {
  check_ring(bin.outer, source, "hide outline");
  const double area_m2 = std::abs(signed_area(bin.outer)) * 1e-6;
  if (area_m2 < kSmallestHide_m2 || area_m2 > kLargestHide_m2) {
    char text[160];
    std::snprintf(text, sizeof text, "the hide outline encloses %.3g m^2, outside %.2f..%.0f m^2; check the drawing's units",
                  area_m2, kSmallestHide_m2, kLargestHide_m2);
    throw EngineError(source + ": " + text);
  }
  for (size_t h = 0; h < bin.holes.size(); ++h) {
    const std::string what = "hole " + std::to_string(h + 1);
    check_ring(bin.holes[h], source, what);
    check_inside(bin.holes[h], bin.outer, source, what);
  }
  for (size_t z = 0; z < bin.zones.size(); ++z) {
    const std::string what = "zone " + std::to_string(z + 1) + " (grade " + std::to_string(bin.zones[z].quality) + ")";
    check_ring(bin.zones[z].shape, source, what);
    check_inside(bin.zones[z].shape, bin.outer, source, what);
  }
}

}  // namespace lastcut
