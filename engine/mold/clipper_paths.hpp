#pragma once
// Conversions between Polygon2 / point lists (mm) and Clipper's integer paths.
// Clipper works on integers: 1 unit = 10 nm, far below any cutter's resolution.
#include <polyclipping/clipper.hpp>

#include <cmath>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/core/polygon.hpp"

namespace lastcut {

inline constexpr double kClipperUnitsPerMm = 1e5;

inline ClipperLib::Path to_clipper_path(const std::vector<Point2>& points_mm) {
  ClipperLib::Path path;
  path.reserve(points_mm.size());
  for (const auto& p : points_mm)
    path.emplace_back(static_cast<ClipperLib::cInt>(std::llround(p.x() * kClipperUnitsPerMm)),
                      static_cast<ClipperLib::cInt>(std::llround(p.y() * kClipperUnitsPerMm)));
  return path;
}

inline Polygon2 from_clipper_path(const ClipperLib::Path& path) {
  Polygon2 polygon;
  polygon.points.reserve(path.size());
  for (const auto& q : path)
    polygon.points.emplace_back(static_cast<double>(q.X) / kClipperUnitsPerMm, static_cast<double>(q.Y) / kClipperUnitsPerMm);
  return polygon;
}

// The ring of largest area (the outer boundary when growing a simple polygon), or nullptr.
inline const ClipperLib::Path* largest_ring(const ClipperLib::Paths& paths) {
  const ClipperLib::Path* outer = nullptr;
  double outer_area = 0.0;
  for (const auto& candidate : paths) {
    const double area = std::abs(ClipperLib::Area(candidate));
    if (area > outer_area) outer_area = area, outer = &candidate;
  }
  return outer;
}

// The outer ring of a grown outline as a counter-clockwise polygon (mm), with the vertices within half
// of tolerance_mm of their neighbours' line dropped: where two grown shapes meet, Clipper's chord error
// leaves steps of micrometres that would turn the knife by up to 90 degrees. Throws EngineError when
// there is no ring.
inline Polygon2 outer_cut_outline(const ClipperLib::Paths& grown, double tolerance_mm) {
  const ClipperLib::Path* outer = largest_ring(grown);
  if (outer == nullptr) throw EngineError("allowance offset produced no outline");
  ClipperLib::Path ring = *outer;
  ClipperLib::CleanPolygon(ring, 0.5 * tolerance_mm * kClipperUnitsPerMm);
  Polygon2 outline = from_clipper_path(ring);
  make_counter_clockwise(outline);
  return outline;
}

}  // namespace lastcut
