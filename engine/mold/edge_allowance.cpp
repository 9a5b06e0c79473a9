#include "engine/mold/edge_allowance.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/core/engine_error.hpp"
#include "engine/mold/clipper_paths.hpp"

namespace lastcut {

namespace {

// Landmarks adjacent around the outline, either direction, and the edge between them.
struct EdgeRule {
  const char* a;
  const char* b;
  EdgeKind kind;
};
constexpr EdgeRule kEdgeRules[] = {{"toe", "heel", EdgeKind::Feather},
                                   {"heel", "top_back", EdgeKind::BackSeam},
                                   {"top_back", "top_front", EdgeKind::Top},
                                   {"top_front", "toe", EdgeKind::FrontSeam}};

// The fillet zone around a transition, in multiples of the larger allowance: a fillet of radius
// r against a corner at most r from the landmark ends within about 2.4 r of it.
constexpr double kFilletZoneFactor = 3.0;

ClipperLib::Paths offset_paths(const ClipperLib::Paths& paths, ClipperLib::EndType ends, double delta_mm,
                               double tolerance_mm) {
  // Half the tolerance: Clipper's chords of the round parts then stay well within it.
  ClipperLib::ClipperOffset offset(2.0, std::max(0.5 * tolerance_mm, 0.001) * kClipperUnitsPerMm);
  offset.AddPaths(paths, ClipperLib::jtRound, ends);
  ClipperLib::Paths solution;
  offset.Execute(solution, delta_mm * kClipperUnitsPerMm);
  return solution;
}

ClipperLib::Paths combine(const ClipperLib::Paths& subject, const ClipperLib::Paths& clip, ClipperLib::ClipType type) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(subject, ClipperLib::ptSubject, true);
  clipper.AddPaths(clip, ClipperLib::ptClip, true);
  ClipperLib::Paths solution;
  clipper.Execute(type, solution, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return solution;
}

ClipperLib::Path disc(const Point2& center_mm, double radius_mm, double tolerance_mm) {
  // Chord error radius * (1 - cos(pi / n)) <= tolerance.
  const double step_rad = 2.0 * std::acos(std::max(-1.0, 1.0 - tolerance_mm / radius_mm));
  const int n = std::max(16, static_cast<int>(std::ceil(2.0 * std::numbers::pi / step_rad)));
  std::vector<Point2> points;
  for (int k = 0; k < n; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / n;
    points.push_back(center_mm + radius_mm * Point2(std::cos(angle), std::sin(angle)));
  }
  return to_clipper_path(points);
}

}  // namespace

std::string to_string(EdgeKind kind) {
  switch (kind) {
    case EdgeKind::Feather: return "feather";
    case EdgeKind::FrontSeam: return "seam_front";
    case EdgeKind::BackSeam: return "seam_back";
    case EdgeKind::Top: return "top";
  }
  return "?";
}

double allowance_of(const EdgeAllowances& allowances, EdgeKind kind) {
  switch (kind) {
    case EdgeKind::Feather: return allowances.lasting_mm;
    case EdgeKind::FrontSeam:
    case EdgeKind::BackSeam: return allowances.seam_mm;
    case EdgeKind::Top: return allowances.top_mm;
  }
  return 0.0;
}

std::vector<NetEdge> split_net_edges(const Polygon2& net, const std::vector<std::pair<std::string, int>>& landmark_index) {
  const int n = static_cast<int>(net.points.size());
  std::vector<std::pair<int, std::string>> around;
  for (const char* name : kEdgeLandmarks) {
    const auto found = std::find_if(landmark_index.begin(), landmark_index.end(),
                                    [&](const auto& entry) { return entry.first == name; });
    if (found == landmark_index.end() || found->second < 0 || found->second >= n)
      throw EngineError(std::string("per-edge allowances need the landmark ") + name + " on the outline");
    around.emplace_back(found->second, name);
  }
  std::sort(around.begin(), around.end());
  for (size_t i = 0; i + 1 < around.size(); ++i)
    if (around[i].first == around[i + 1].first)
      throw EngineError("landmarks " + around[i].second + " and " + around[i + 1].second +
                        " fall on the same outline point; the mold edges cannot be told apart");

  std::vector<NetEdge> edges;
  for (size_t i = 0; i < around.size(); ++i) {
    // Named references rather than structured bindings: clang 14 (the fuzzing build) cannot capture
    // structured bindings in a lambda.
    const int start = around[i].first;
    const std::string& from = around[i].second;
    const int end = around[(i + 1) % around.size()].first;
    const std::string& to = around[(i + 1) % around.size()].second;
    const auto rule = std::find_if(std::begin(kEdgeRules), std::end(kEdgeRules), [&](const EdgeRule& r) {
      return (from == r.a && to == r.b) || (from == r.b && to == r.a);
    });
    if (rule == std::end(kEdgeRules))
      throw EngineError("landmarks " + from + " and " + to +
                        " are neighbours on the outline; expected the order toe, heel, top_back, top_front");
    NetEdge edge;
    edge.kind = rule->kind;
    edge.from = from;
    edge.to = to;
    for (int k = start;; k = (k + 1) % n) {
      edge.points.push_back(net.points[static_cast<size_t>(k)]);
      if (k == end) break;
    }
    edges.push_back(std::move(edge));
  }
  return edges;
}

Polygon2 grow_by_edge_allowances(const Polygon2& net, const std::vector<NetEdge>& edges,
                                 const EdgeAllowances& allowances, double tolerance_mm) {
  std::vector<AllowanceEdge> grown_edges;
  for (const NetEdge& edge : edges) grown_edges.push_back({edge.points, allowance_of(allowances, edge.kind)});
  return grow_by_allowances(net, grown_edges, tolerance_mm);
}

Polygon2 grow_by_allowances(const Polygon2& net, const std::vector<AllowanceEdge>& edges, double tolerance_mm) {
  for (const AllowanceEdge& edge : edges)
    if (!(edge.allowance_mm >= 0.0) || !std::isfinite(edge.allowance_mm))
      throw EngineError("every edge allowance must be a finite number of millimetres >= 0");
  if (!(tolerance_mm > 0.0)) throw EngineError("the allowance tolerance must be positive");

  ClipperLib::Paths grown{to_clipper_path(net.points)};
  for (const AllowanceEdge& edge : edges) {
    const double distance_mm = edge.allowance_mm;
    if (distance_mm <= 0.0) continue;
    const ClipperLib::Paths band =
        offset_paths({to_clipper_path(edge.points)}, ClipperLib::etOpenRound, distance_mm, tolerance_mm);
    grown = combine(grown, band, ClipperLib::ctUnion);
  }

  // Fillets where two different allowances meet: the closing of the grown shape, kept only near
  // the landmark so the rest of the outline stays at its exact distances.
  for (size_t i = 0; i < edges.size(); ++i) {
    const AllowanceEdge& before = edges[i];
    const AllowanceEdge& after = edges[(i + 1) % edges.size()];
    const double d1 = before.allowance_mm, d2 = after.allowance_mm;
    if (d1 == d2) continue;
    const double radius_mm = std::max(d1, d2);
    const ClipperLib::Paths closed =
        offset_paths(offset_paths(grown, ClipperLib::etClosedPolygon, radius_mm, tolerance_mm),
                     ClipperLib::etClosedPolygon, -radius_mm, tolerance_mm);
    const ClipperLib::Paths near =
        combine(closed, {disc(before.points.back(), kFilletZoneFactor * radius_mm, tolerance_mm)}, ClipperLib::ctIntersection);
    grown = combine(grown, near, ClipperLib::ctUnion);
  }

  // Growing a simple polygon gives one outer ring (and possibly holes where narrow bays close).
  return outer_cut_outline(grown, tolerance_mm);
}

}  // namespace lastcut
