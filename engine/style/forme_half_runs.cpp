#include "engine/style/forme_half_runs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

constexpr double kInsideHalf_mm = 1e-9;   // closer than this to the half's triangles is inside them
constexpr int kOutlineHalvings = 40;      // a 1 mm step found to 1e-12 mm
constexpr double kEndPastLine_mm = 0.05;  // an end moved onto another line goes this far past it, so the
                                          // pieces' cut along it meets the other line's (upper_regions.hpp)

const char* half_word(int half) { return half == 0 ? "medial" : "lateral"; }

std::string line_words(const FormeDrawing& drawing, std::size_t line) {
  const FormeLineDrawing& drawn = drawing.lines[line];
  return drawing.source + ": line " + drawn.name + " (layer " + drawn.layer + ")";
}

// The point of a polyline nearest to p: segment index, weight of its second point, distance and point.
struct PolylineSpot {
  std::size_t segment = 0;
  double weight = 0, distance_mm = std::numeric_limits<double>::infinity();
  Point2 at = Point2::Zero();
};

PolylineSpot nearest_on(const std::vector<Point2>& polyline, const Point2& p) {
  PolylineSpot best;
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
    const Point2 ab = polyline[i + 1] - polyline[i];
    const double t = std::clamp((p - polyline[i]).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    const Point2 at = polyline[i] + t * ab;
    if ((at - p).norm() < best.distance_mm) best = {i, t, (at - p).norm(), at};
  }
  return best;
}

// The point of the half's outline closest to a point outside it.
Point2 onto_outline(const FormeHalfShape& half, const Point2& outside) {
  const SurfaceHit hit = half.triangles.closest(outside);
  Point2 on = Point2::Zero();
  for (int k = 0; k < 3; ++k) on += hit.barycentric(k) * half.layout->forme_uv_mm.row(half.layout->segment->mesh3d.F(hit.face, k)).transpose();
  return on;
}

// Where the segment from `outside` to `inside` crosses the half's outline: found by bisection, returned on the outline.
Point2 outline_crossing(const FormeHalfShape& half, Point2 outside, Point2 inside) {
  for (int k = 0; k < kOutlineHalvings; ++k) {
    const Point2 middle = 0.5 * (outside + inside);
    (half.outside_mm(middle) > kInsideHalf_mm ? outside : inside) = middle;
  }
  return onto_outline(half, outside);
}

// One stretch of points within the grace of the half, [begin, end), as a run: cut where it crosses the
// outline at either end, the points outside it in between moved onto it. Nothing when no point is inside.
std::optional<HalfRun> run_from(const FormeHalfShape& half, const std::vector<Point2>& points, const std::vector<double>& outside,
                                std::size_t begin, std::size_t end) {
  std::size_t first = begin;
  while (first < end && outside[first] > kInsideHalf_mm) ++first;
  if (first == end) return std::nullopt;
  std::size_t last = end - 1;
  while (outside[last] > kInsideHalf_mm) --last;
  HalfRun run;
  if (first > begin) run.points_mm.push_back(outline_crossing(half, points[first - 1], points[first]));
  for (std::size_t i = first; i <= last; ++i)
    run.points_mm.push_back(outside[i] > kInsideHalf_mm ? onto_outline(half, points[i]) : points[i]);
  if (last + 1 < end) run.points_mm.push_back(outline_crossing(half, points[last + 1], points[last]));
  if (run.points_mm.size() < 2) return std::nullopt;
  return run;
}

}  // namespace

FormeHalfShape::FormeHalfShape(const FormeHalfLayout& laid)
    : layout(&laid), triangles(laid.forme_uv_mm, laid.segment->mesh3d.F) {}

double FormeHalfShape::outside_mm(const Point2& forme_point) const {
  const double distance_mm = triangles.closest(forme_point).distance_mm;
  return distance_mm <= kInsideHalf_mm ? 0.0 : distance_mm;
}

Eigen::Vector3d FormeHalfShape::surface_point(const Point2& forme_point) const {
  const SurfaceHit hit = triangles.closest(forme_point);
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) point += hit.barycentric(k) * layout->segment->mesh3d.V.row(layout->segment->mesh3d.F(hit.face, k)).transpose();
  return point;
}

std::vector<Point2> densified(const std::vector<Point2>& points, double step_mm) {
  std::vector<Point2> out{points.front()};
  for (std::size_t i = 1; i < points.size(); ++i) {
    const int pieces = std::max(1, static_cast<int>(std::ceil((points[i] - points[i - 1]).norm() / step_mm)));
    for (int k = 1; k < pieces; ++k) out.push_back(points[i - 1] + (points[i] - points[i - 1]) * (static_cast<double>(k) / pieces));
    out.push_back(points[i]);  // exactly: a closed line stays closed
  }
  return out;
}

std::vector<HalfRun> runs_on_half(const FormeDrawing& drawing, std::size_t line, const std::vector<Point2>& points,
                                  const FormeHalfShape& half, int half_index, const std::vector<double>& outside_elsewhere) {
  std::vector<double> outside(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    outside[i] = half.outside_mm(points[i]);
    if (outside[i] > kFormeOutsideGrace_mm && outside_elsewhere[i] > kFormeOutsideGrace_mm) {
      char distance[32];
      std::snprintf(distance, sizeof distance, "%.1f", std::min(outside[i], outside_elsewhere[i]));
      const bool one_half = std::isinf(outside_elsewhere[i]);
      throw EngineError(line_words(drawing, line) + " runs " + distance + " mm outside the " +
                        (one_half ? std::string(half_word(half_index)) + " half" : std::string("forme")) + " at " +
                        forme_point_text(points[i]) + ": a line lies on the forme, at most 2 mm past its outline");
    }
  }
  const bool closed = points.size() > 2 && points.front() == points.back();
  std::vector<HalfRun> runs;
  if (closed && *std::max_element(outside.begin(), outside.end()) <= kInsideHalf_mm) {
    HalfRun loop;
    loop.points_mm = points;
    loop.closed = true;
    runs.push_back(loop);
  } else {
    // A closed line is opened where it lies farthest outside the half, so no stretch on it wraps past its first point.
    std::vector<Point2> open = points;
    std::vector<double> open_outside = outside;
    if (closed) {
      const auto far = static_cast<std::size_t>(std::max_element(outside.begin(), outside.end() - 1) - outside.begin());
      open.assign(points.begin() + static_cast<std::ptrdiff_t>(far), points.end() - 1);
      open.insert(open.end(), points.begin(), points.begin() + static_cast<std::ptrdiff_t>(far) + 1);
      open_outside.assign(outside.begin() + static_cast<std::ptrdiff_t>(far), outside.end() - 1);
      open_outside.insert(open_outside.end(), outside.begin(), outside.begin() + static_cast<std::ptrdiff_t>(far) + 1);
    }
    for (std::size_t begin = 0; begin < open.size();) {
      if (open_outside[begin] > kFormeOutsideGrace_mm) {
        ++begin;
        continue;
      }
      std::size_t end = begin;
      while (end < open.size() && open_outside[end] <= kFormeOutsideGrace_mm) ++end;
      if (std::optional<HalfRun> run = run_from(half, open, open_outside, begin, end)) runs.push_back(std::move(*run));
      begin = end;
    }
  }
  for (HalfRun& run : runs) run.half = half_index, run.line = line;
  return runs;
}

void settle_run_ends(const FormeDrawing& drawing, const FormeHalfShape& half, std::vector<HalfRun>& runs) {
  const std::array<std::pair<RunEndKind, EdgeKind>, 4> edges = {{{RunEndKind::Feather, EdgeKind::Feather},
                                                                  {RunEndKind::Top, EdgeKind::Top},
                                                                  {RunEndKind::FrontSeam, EdgeKind::FrontSeam},
                                                                  {RunEndKind::BackSeam, EdgeKind::BackSeam}}};
  std::array<std::vector<Point2>, 4> edge_points;
  for (std::size_t e = 0; e < 4; ++e) edge_points[e] = half.layout->edge_points(edges[e].second);
  const std::vector<HalfRun> as_drawn = runs;  // ends are moved onto other lines as they were drawn
  for (HalfRun& run : runs) {
    if (run.closed) continue;
    for (const bool at_last : {false, true}) {
      Point2& end = at_last ? run.points_mm.back() : run.points_mm.front();
      const Point2& before = at_last ? run.points_mm[run.points_mm.size() - 2] : run.points_mm[1];
      RunEnd& settled = at_last ? run.last : run.first;
      PolylineSpot best;
      int on_edge = -1;  // index into edges, or -1: on another line
      for (std::size_t e = 0; e < 4; ++e)
        if (const PolylineSpot spot = nearest_on(edge_points[e], end); spot.distance_mm < best.distance_mm)
          best = spot, on_edge = static_cast<int>(e);
      for (const HalfRun& other : as_drawn)
        if (other.line != run.line)
          if (const PolylineSpot spot = nearest_on(other.points_mm, end); spot.distance_mm < best.distance_mm) best = spot, on_edge = -1;
      if (!(best.distance_mm <= kFormeEndReach_mm))
        throw EngineError(line_words(drawing, run.line) + " ends inside the upper at " + forme_point_text(end) + " on the " +
                          half_word(run.half) +
                          " half: end it on the feather line, the top edge, the centre line or another line (within 1 mm)");
      if (on_edge < 0) {
        settled.kind = RunEndKind::Line;
        const Point2 along = best.at - before;
        end = best.at + kEndPastLine_mm * (along.norm() > 0 ? along.normalized() : Point2::Zero());
        continue;
      }
      const auto& [end_kind, edge_kind] = edges[static_cast<std::size_t>(on_edge)];
      const FormeEdge& edge = half.layout->boundary.edge(edge_kind);
      settled = {end_kind, best.segment, best.weight,
                 (1 - best.weight) * edge.share[best.segment] + best.weight * edge.share[best.segment + 1]};
      end = best.at;
    }
  }
}

}  // namespace lastcut
