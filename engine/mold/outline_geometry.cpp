#include "engine/mold/outline_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <unordered_map>
#include <vector>

#include "engine/core/segment_predicates.hpp"

namespace lastcut {

namespace {

bool adjacent(int i, int j, int n) { return i == j || (i + 1) % n == j || (j + 1) % n == i; }

// Calls visit(i, j) with i < j for every pair of non-adjacent touching edges until it returns false.
template <typename Visit>
void for_each_intersection(const Polygon2& polygon, Visit visit) {
  const auto& p = polygon.points;
  const int n = static_cast<int>(p.size());
  if (n < 4) return;
  double total_length = 0.0;
  for (int i = 0; i < n; ++i) total_length += (p[(i + 1) % n] - p[i]).norm();
  const double cell = std::max(2.0 * total_length / n, 1e-9);
  Point2 lo = p[0];
  for (const auto& q : p) lo = lo.cwiseMin(q);
  auto cell_of = [&](double value, double origin) { return static_cast<std::int64_t>(std::floor((value - origin) / cell)); };

  std::unordered_map<std::int64_t, std::vector<int>> grid;
  for (int i = 0; i < n; ++i) {
    const Point2& a = p[i];
    const Point2& b = p[(i + 1) % n];
    const std::int64_t x0 = cell_of(std::min(a.x(), b.x()), lo.x()), x1 = cell_of(std::max(a.x(), b.x()), lo.x());
    const std::int64_t y0 = cell_of(std::min(a.y(), b.y()), lo.y()), y1 = cell_of(std::max(a.y(), b.y()), lo.y());
    for (std::int64_t x = x0; x <= x1; ++x)
      for (std::int64_t y = y0; y <= y1; ++y) grid[x * 4000037 + y].push_back(i);
  }
  std::set<std::pair<int, int>> seen;
  for (const auto& [key, edges] : grid) {
    for (size_t s = 0; s < edges.size(); ++s) {
      for (size_t t = s + 1; t < edges.size(); ++t) {
        const int i = std::min(edges[s], edges[t]);
        const int j = std::max(edges[s], edges[t]);
        if (adjacent(i, j, n)) continue;
        if (!segments_touch(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n])) continue;
        if (!seen.emplace(i, j).second) continue;
        if (!visit(i, j)) return;
      }
    }
  }
}

}  // namespace

std::optional<std::pair<int, int>> find_self_intersection(const Polygon2& polygon) {
  std::optional<std::pair<int, int>> found;
  for_each_intersection(polygon, [&](int i, int j) {
    found = std::make_pair(i, j);
    return false;
  });
  return found;
}

std::vector<std::pair<int, int>> find_self_intersections(const Polygon2& polygon) {
  std::vector<std::pair<int, int>> found;
  for_each_intersection(polygon, [&](int i, int j) {
    found.emplace_back(i, j);
    return true;
  });
  std::sort(found.begin(), found.end());
  return found;
}

OutlinePoint closest_outline_point(const Polygon2& polygon, const Point2& p) {
  OutlinePoint best;
  best.distance_mm = std::numeric_limits<double>::infinity();
  const auto& q = polygon.points;
  const int n = static_cast<int>(q.size());
  for (int i = 0; i < n; ++i) {
    const Point2& a = q[i];
    const Point2 ab = q[(i + 1) % n] - a;
    const double length_squared = ab.squaredNorm();
    const double t = length_squared > 0.0 ? std::clamp((p - a).dot(ab) / length_squared, 0.0, 1.0) : 0.0;
    const Point2 candidate = a + t * ab;
    const double distance = (candidate - p).norm();
    if (distance < best.distance_mm) best = {candidate, i, distance};
  }
  return best;
}

Point2 inward_normal(const Polygon2& polygon, int edge) {
  const auto& q = polygon.points;
  const Point2 direction = q[(edge + 1) % q.size()] - q[edge];
  const double length = direction.norm();
  if (length == 0.0) return Point2::Zero();
  // Interior of a counter-clockwise polygon lies to the left of each edge.
  return Point2(-direction.y(), direction.x()) / length;
}

}  // namespace lastcut
