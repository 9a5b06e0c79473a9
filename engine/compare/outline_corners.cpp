#include "engine/compare/outline_corners.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "engine/core/engine_error.hpp"
#include "engine/mold/outline_geometry.hpp"

namespace lastcut {

namespace {

// Points every `step` of arc length exactly (the last step absorbs the remainder).
std::vector<Point2> resample_uniform(const Polygon2& outline, double step_mm) {
  const double length = perimeter(outline);
  const int count = std::max(3, static_cast<int>(std::ceil(length / step_mm)));
  const double step = length / count;
  std::vector<Point2> samples;
  samples.reserve(static_cast<size_t>(count));
  const auto& p = outline.points;
  size_t edge = 0;
  double edge_start = 0.0;  // arc length at p[edge]
  for (int k = 0; k < count; ++k) {
    const double s = k * step;
    while (edge + 1 < p.size() && edge_start + (p[(edge + 1) % p.size()] - p[edge]).norm() < s)
      edge_start += (p[(edge + 1) % p.size()] - p[edge]).norm(), ++edge;
    const Point2& a = p[edge];
    const Point2& b = p[(edge + 1) % p.size()];
    const double edge_length = (b - a).norm();
    const double t = edge_length > 0.0 ? std::clamp((s - edge_start) / edge_length, 0.0, 1.0) : 0.0;
    samples.push_back(a + t * (b - a));
  }
  return samples;
}

// A polygon's corner is one of its vertices; the resampling only finds it within a sample step.
Point2 snapped_to_vertex(const Polygon2& outline, const Point2& at, double reach_mm) {
  Point2 best = at;
  double best_distance = reach_mm;
  for (const auto& p : outline.points)
    if ((p - at).norm() < best_distance) best_distance = (p - at).norm(), best = p;
  return best;
}

}  // namespace

std::vector<SharpCorner> sharp_corners(const Polygon2& outline, const CornerOptions& options) {
  if (outline.points.size() < 3) throw EngineError("corner search needs an outline of 3 or more points");
  const std::vector<Point2> q = resample_uniform(outline, options.sample_step_mm);
  const int n = static_cast<int>(q.size());
  const int k = std::clamp(static_cast<int>(std::lround(options.window_mm / options.sample_step_mm)), 1, (n - 1) / 2);
  const auto at = [&](int i) -> const Point2& { return q[static_cast<size_t>(((i % n) + n) % n)]; };
  std::vector<double> turn(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const Point2 a = at(i) - at(i - k), b = at(i + k) - at(i);
    turn[static_cast<size_t>(i)] = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)) * 180.0 / std::numbers::pi;
  }
  const auto strength = [&](int i) { return std::abs(turn[static_cast<size_t>(((i % n) + n) % n)]); };
  // Local maxima over +-k; equal neighbours form a run, reported once at its middle.
  std::vector<SharpCorner> corners;
  std::vector<bool> taken(static_cast<size_t>(n), false);
  for (int i = 0; i < n; ++i) {
    if (taken[static_cast<size_t>(i)] || strength(i) < options.min_turn_deg) continue;
    bool is_max = true;
    for (int j = i - k; j <= i + k && is_max; ++j) is_max = strength(j) <= strength(i);
    if (!is_max) continue;
    int first = i, last = i;
    constexpr double kSameTurn_deg = 1e-6;
    while (last - first < n - 1 && std::abs(strength(last + 1) - strength(i)) < kSameTurn_deg) ++last;
    while (last - first < n - 1 && std::abs(strength(first - 1) - strength(i)) < kSameTurn_deg) --first;
    for (int j = first; j <= last; ++j) taken[static_cast<size_t>(((j % n) + n) % n)] = true;
    const int middle = first + (last - first) / 2;
    // Even runs: halfway between the two middle samples.
    const Point2 where = (last - first) % 2 == 0 ? at(middle) : Point2(0.5 * (at(middle) + at(middle + 1)));
    corners.push_back({snapped_to_vertex(outline, where, 2.0 * options.sample_step_mm),
                       turn[static_cast<size_t>(((middle % n) + n) % n)]});
  }
  return corners;
}

std::vector<CornerMatch> match_corners(const Mold& mold, const Mold& reference, const CornerOptions& options) {
  std::vector<CornerMatch> matches;
  if (mold.marks.empty()) return matches;
  const std::vector<SharpCorner> corners = sharp_corners(reference.outline, options);
  for (const auto& mark : mold.marks) {
    CornerMatch match;
    match.name = mark.name;
    match.mold_mm = mark.position_mm;
    const auto named = std::find_if(reference.marks.begin(), reference.marks.end(),
                                    [&](const MoldMark& m) { return m.name == mark.name; });
    if (named != reference.marks.end()) {
      match.reference_mm = named->position_mm;
      match.from_reference_mark = true;
    } else {
      double best = options.search_radius_mm;
      match.found_sharp_corner = false;
      for (const auto& corner : corners) {
        const double distance = (corner.at_mm - mark.position_mm).norm();
        if (distance <= best) best = distance, match.reference_mm = corner.at_mm, match.found_sharp_corner = true;
      }
      if (!match.found_sharp_corner) match.reference_mm = closest_outline_point(reference.outline, mark.position_mm).point;
    }
    match.margin_mm = (match.reference_mm - match.mold_mm).norm();
    matches.push_back(match);
  }
  return matches;
}

}  // namespace lastcut
