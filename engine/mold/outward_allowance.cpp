#include "engine/mold/outward_allowance.hpp"

#include <algorithm>
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

bool turns_left(const Segment& s, const Segment& next) {
  const Point2 d1 = s.b - s.a, d2 = next.b - next.a;
  return d1.x() * d2.y() - d1.y() * d2.x() > 0;
}

// The chamfer on the smaller side of a change of allowance at segments[at].b (see the header): the cut
// line comes down from `larger_mm` at 45 degrees along the segments after `at` (forward) or up to it
// (backward) until it meets their own allowance, as strips of falling height and sectors at convex
// corners, added to `shapes`.
void add_chamfer(const std::vector<Segment>& segments, std::size_t at, bool forward, double larger_mm, double tolerance_mm,
                 ClipperLib::Paths& shapes) {
  const std::size_t n = segments.size();
  double walked_mm = 0;
  for (std::size_t step = 0; step < n; ++step) {
    const std::size_t j = forward ? (at + 1 + step) % n : (at + n - step) % n;
    const Segment& s = segments[j];
    const double height_mm = larger_mm - walked_mm;
    if (height_mm <= s.allowance_mm) return;
    const Point2 near = forward ? s.a : s.b, far = forward ? s.b : s.a;
    const double length_mm = (far - near).norm();
    const double end_mm = std::min(length_mm, height_mm - s.allowance_mm);  // where it meets the strip
    const Point2 end = near + (end_mm / length_mm) * (far - near);
    shapes.push_back(to_clipper_path({near, end, end + (height_mm - end_mm) * s.outward, near + height_mm * s.outward}));
    walked_mm += length_mm;
    if (end_mm < length_mm) return;
    // The corner at `far`, between s and the segment after it along the walk, at the height reached there.
    const Segment& before = forward ? s : segments[(j + n - 1) % n];
    const Segment& after = forward ? segments[(j + 1) % n] : s;
    if (turns_left(before, after)) {
      const std::vector<Point2> fan = sector(far, before.outward, after.outward, larger_mm - walked_mm,
                                             larger_mm - walked_mm, tolerance_mm);
      if (!fan.empty()) shapes.push_back(to_clipper_path(fan));
    }
  }
}

// A change to 0 at the convex corner s.b (one of s and next has no allowance): the raw edge's line runs
// on through its neighbour's allowance. Where the outline turns more than a right angle, that line leans
// past the allowance's square end; the corner is rounded at larger_mm from the square end round to that
// line, which the cut then follows back to the corner. At a right angle or less the square end reaches it.
// (Filling up to where the line meets the allowance's outer line grew horns where the neighbour's last
// segment is short and tilted: a tongue's top edge curving into its raw sides.)
void add_raw_corner(const Segment& s, const Segment& next, double larger_mm, double tolerance_mm, ClipperLib::Paths& shapes) {
  const bool raw_after = next.allowance_mm == 0;
  const Point2 raw_line = raw_after ? Point2(-(next.b - next.a).normalized()) : Point2((s.b - s.a).normalized());
  const Point2 square_end = raw_after ? s.outward : next.outward;
  const Point2 past_end = raw_after ? Point2((s.b - s.a).normalized()) : Point2(-(next.b - next.a).normalized());
  if (raw_line.dot(past_end) <= 0) return;
  // Counter-clockwise from the one to the other: the square end comes first when the raw edge follows.
  const std::vector<Point2> fan = raw_after ? sector(s.b, square_end, raw_line, larger_mm, larger_mm, tolerance_mm)
                                            : sector(s.b, raw_line, square_end, larger_mm, larger_mm, tolerance_mm);
  if (!fan.empty()) shapes.push_back(to_clipper_path(fan));
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
    // turns left (convex); at a right turn the strips overlap. A change of allowance to a smaller one
    // above 0 keeps the larger round the corner and chamfers down on the smaller side; a change to 0
    // runs the raw edge's line on through the allowance (see the header).
    const Segment& next = segments[(i + 1) % segments.size()];
    const double larger_mm = std::max(s.allowance_mm, next.allowance_mm), smaller_mm = std::min(s.allowance_mm, next.allowance_mm);
    const bool chamfer = smaller_mm > 0 && larger_mm > smaller_mm;
    if (chamfer) add_chamfer(segments, i, next.allowance_mm < s.allowance_mm, larger_mm, tolerance_mm, shapes);
    if (!turns_left(s, next)) continue;
    if (smaller_mm == 0 && larger_mm > 0) {
      add_raw_corner(s, next, larger_mm, tolerance_mm, shapes);
    } else {
      const std::vector<Point2> fan = sector(s.b, s.outward, next.outward, chamfer ? larger_mm : s.allowance_mm,
                                             chamfer ? larger_mm : next.allowance_mm, tolerance_mm);
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
