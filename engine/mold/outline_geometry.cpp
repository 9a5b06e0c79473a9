#include "engine/mold/outline_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/core/near_edge_pairs.hpp"
#include "engine/core/segment_predicates.hpp"

namespace lastcut {

namespace {

// Calls visit(i, j) for every pair of edges that share no vertex and touch, until it returns false.
// Throws EngineError for a point that is not a finite number.
template <typename Visit>
void for_each_intersection(const Polygon2& polygon, Visit visit) {
  const auto& p = polygon.points;
  const int n = static_cast<int>(p.size());
  const EdgePairScan scan = for_each_near_edge_pair(
      n, [&](int k) { return p[static_cast<size_t>(k)]; }, 0.0,
      [&](int i, int j) {
        if (!segments_touch(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n])) return true;
        return visit(std::min(i, j), std::max(i, j));
      });
  if (scan == EdgePairScan::NotFinite) throw EngineError("outline check: a point of the outline is not a finite number");
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
