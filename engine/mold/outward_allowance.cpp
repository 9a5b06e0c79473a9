#include "engine/mold/outward_allowance.hpp"

#include <cmath>
#include <numbers>

#include "engine/core/engine_error.hpp"
#include "engine/mold/clipper_paths.hpp"

namespace lastcut {
namespace {

struct Segment {
  Point2 a, b;
  double allowance_mm;
  Point2 outward;  // unit; right of a -> b on a counter-clockwise outline
};

// The sector at corner c from direction `from` to `to` (unit vectors, turning counter-clockwise) with
// its radius going from r_from to r_to, as a fan polygon. Empty when both radii are 0.
std::vector<Point2> sector(const Point2& c, const Point2& from, const Point2& to, double r_from, double r_to, double tolerance_mm) {
  double turn = std::atan2(from.x() * to.y() - from.y() * to.x(), from.dot(to));
  if (turn < 0) turn += 2 * std::numbers::pi;  // always counter-clockwise from `from` to `to`
  const double radius = std::max(r_from, r_to);
  if (!(radius > 0) || turn <= 0) return {};
  const double step = 2 * std::acos(std::max(-1.0, 1 - tolerance_mm / radius));
  const int pieces = std::max(1, static_cast<int>(std::ceil(turn / std::max(step, 1e-3))));
  std::vector<Point2> fan{c};
  const double start = std::atan2(from.y(), from.x());
  for (int k = 0; k <= pieces; ++k) {
    const double t = static_cast<double>(k) / pieces;
    const double angle = start + t * turn;
    fan.push_back(c + ((1 - t) * r_from + t * r_to) * Point2(std::cos(angle), std::sin(angle)));
  }
  return fan;
}

}  // namespace

Polygon2 grow_outward_by_allowances(const Polygon2& net, const std::vector<AllowanceEdge>& edges, double tolerance_mm) {
  if (!(tolerance_mm > 0.0)) throw EngineError("the allowance tolerance must be positive");
  std::vector<Segment> segments;
  for (const AllowanceEdge& edge : edges) {
    if (!(edge.allowance_mm >= 0.0) || !std::isfinite(edge.allowance_mm))
      throw EngineError("every edge allowance must be a finite number of millimetres >= 0");
    for (std::size_t i = 1; i < edge.points.size(); ++i) {
      const Point2 a = edge.points[i - 1], b = edge.points[i];
      if ((b - a).norm() == 0) continue;
      const Point2 along = (b - a).normalized();
      segments.push_back({a, b, edge.allowance_mm, Point2(along.y(), -along.x())});
    }
  }
  ClipperLib::Paths shapes{to_clipper_path(net.points)};
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment& s = segments[i];
    if (s.allowance_mm > 0)
      shapes.push_back(to_clipper_path({s.a, s.b, s.b + s.allowance_mm * s.outward, s.a + s.allowance_mm * s.outward}));
    // The corner at s.b, from this segment's normal round to the next one's: only where the outline
    // turns left (convex); at a right turn the strips overlap.
    const Segment& next = segments[(i + 1) % segments.size()];
    const Point2 d1 = s.b - s.a, d2 = next.b - next.a;
    if (d1.x() * d2.y() - d1.y() * d2.x() > 0) {
      const std::vector<Point2> fan = sector(s.b, s.outward, next.outward, s.allowance_mm, next.allowance_mm, tolerance_mm);
      if (!fan.empty()) shapes.push_back(to_clipper_path(fan));
    }
  }
  // All counter-clockwise: under the non-zero rule a clockwise strip over the net would cancel it.
  for (ClipperLib::Path& shape : shapes)
    if (!ClipperLib::Orientation(shape)) ClipperLib::ReversePath(shape);
  ClipperLib::Clipper clipper;
  clipper.AddPaths(shapes, ClipperLib::ptSubject, true);
  ClipperLib::Paths grown;
  clipper.Execute(ClipperLib::ctUnion, grown, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return outer_cut_outline(grown, tolerance_mm);
}

}  // namespace lastcut
