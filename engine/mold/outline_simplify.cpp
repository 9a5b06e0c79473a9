#include "engine/mold/outline_simplify.hpp"

#include <algorithm>
#include <utility>

#include "engine/core/engine_error.hpp"
#include "engine/mold/outline_geometry.hpp"

namespace lastcut {

namespace {

// Index strictly between from and to (cyclic, to may wrap past n) farthest from chord from-to;
// -1 when there is none.
std::pair<int, double> farthest_between(const std::vector<Point2>& p, int from, int to) {
  const int n = static_cast<int>(p.size());
  int best = -1;
  double best_distance = -1.0;
  for (int k = from + 1; k < to; ++k) {
    const double distance = distance_to_segment(p[k % n], p[from % n], p[to % n]);
    if (distance > best_distance) {
      best_distance = distance;
      best = k;
    }
  }
  return {best, best_distance};
}

// Classic recursive Douglas-Peucker on the cyclic span [from, to] (explicit stack: outlines of
// 100k-triangle halves have thousands of points).
void douglas_peucker(const std::vector<Point2>& p, int from, int to, double tolerance_mm, std::vector<char>& kept) {
  const int n = static_cast<int>(p.size());
  std::vector<std::pair<int, int>> spans{{from, to}};
  while (!spans.empty()) {
    const auto [a, b] = spans.back();
    spans.pop_back();
    const auto [k, distance] = farthest_between(p, a, b);
    if (k < 0 || distance <= tolerance_mm) continue;
    kept[k % n] = 1;
    spans.emplace_back(a, k);
    spans.emplace_back(k, b);
  }
}

std::vector<int> kept_indices(const std::vector<char>& kept) {
  std::vector<int> indices;
  for (int i = 0; i < static_cast<int>(kept.size()); ++i)
    if (kept[i]) indices.push_back(i);
  return indices;
}

}  // namespace

Polygon2 select_points(const Polygon2& polygon, const std::vector<int>& indices) {
  Polygon2 result;
  result.points.reserve(indices.size());
  for (int i : indices) result.points.push_back(polygon.points[i]);
  return result;
}

std::vector<int> simplify_outline(const Polygon2& polygon, double tolerance_mm, const std::vector<int>& keep) {
  const auto& p = polygon.points;
  const int n = static_cast<int>(p.size());
  if (tolerance_mm < 0.0) throw EngineError("simplification tolerance must not be negative");
  if (n <= 3) {
    std::vector<int> all(n);
    for (int i = 0; i < n; ++i) all[i] = i;
    return all;
  }
  std::vector<char> kept(n, 0);
  // Anchor the closed curve at point 0 and the point farthest from it, then at the landmarks.
  int far = 1;
  for (int i = 1; i < n; ++i)
    if ((p[i] - p[0]).squaredNorm() > (p[far] - p[0]).squaredNorm()) far = i;
  kept[0] = kept[far] = 1;
  for (int index : keep)
    if (index >= 0 && index < n) kept[index] = 1;
  std::vector<int> anchors = kept_indices(kept);
  for (size_t s = 0; s < anchors.size(); ++s) {
    const int from = anchors[s];
    const int to = s + 1 < anchors.size() ? anchors[s + 1] : anchors[0] + n;
    douglas_peucker(p, from, to, tolerance_mm, kept);
  }

  // A triangle at least: a closed outline of two points is no outline.
  std::vector<int> indices = kept_indices(kept);
  while (indices.size() < 3) {
    int best_k = -1;
    double best_distance = -1.0;
    for (size_t s = 0; s < indices.size(); ++s) {
      const int from = indices[s];
      const int to = s + 1 < indices.size() ? indices[s + 1] : indices[0] + n;
      const auto [k, distance] = farthest_between(p, from, to);
      if (k >= 0 && distance > best_distance) {
        best_distance = distance;
        best_k = k;
      }
    }
    kept[best_k % n] = 1;
    indices = kept_indices(kept);
  }

  // Repair: split every chord that takes part in a crossing at its farthest dropped point.
  for (;;) {
    const Polygon2 simplified = select_points(polygon, indices);
    const auto crossings = find_self_intersections(simplified);
    if (crossings.empty()) break;
    const int m = static_cast<int>(indices.size());
    bool refined = false;
    for (const auto& [i, j] : crossings) {
      for (int edge : {i, j}) {
        const int from = indices[edge];
        const int to = edge + 1 < m ? indices[edge + 1] : indices[0] + n;
        const auto [k, distance] = farthest_between(p, from, to);
        if (k >= 0 && !kept[k % n]) {
          kept[k % n] = 1;
          refined = true;
        }
      }
    }
    if (!refined) throw EngineError("outline overlaps itself; it cannot be cut as one piece");
    indices = kept_indices(kept);
  }
  return indices;
}

}  // namespace lastcut
