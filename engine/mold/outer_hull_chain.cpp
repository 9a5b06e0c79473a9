#include "engine/mold/outer_hull_chain.hpp"

#include <algorithm>
#include <numeric>

namespace lastcut {

std::vector<Point2> outer_hull_chain(const std::vector<Point2>& points) {
  if (points.size() < 3) return points;
  const Point2 chord = points.back() - points.front();
  const double length = chord.norm();
  if (!(length > 0)) return points;
  const Point2 along = chord / length, left(-along.y(), along.x());
  // Each point in the chord's frame: u along it, v to its left (inward); the outward chain is the lower hull.
  std::vector<Point2> frame(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point2 d = points[i] - points.front();
    frame[i] = Point2(d.dot(along), d.dot(left));
  }
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return frame[a].x() < frame[b].x() || (frame[a].x() == frame[b].x() && frame[a].y() < frame[b].y());
  });
  if (order.front() != 0 || order.back() != points.size() - 1) return points;
  const auto turns_left = [&](std::size_t o, std::size_t a, std::size_t b) {
    const Point2 oa = frame[a] - frame[o], ob = frame[b] - frame[o];
    return oa.x() * ob.y() - oa.y() * ob.x() > 0;
  };
  std::vector<std::size_t> lower;
  for (const std::size_t i : order) {
    while (lower.size() >= 2 && !turns_left(lower[lower.size() - 2], lower.back(), i)) lower.pop_back();
    lower.push_back(i);
  }
  std::vector<Point2> chain;
  for (const std::size_t i : lower) chain.push_back(points[i]);
  return chain;
}

}  // namespace lastcut
