#include "engine/segment/expert_split_plane.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

// Points where the closed polyline crosses the level coordinate(p) = level (edges cut linearly,
// which is exact for the affine coordinates used here).
template <typename Coordinate>
std::vector<Eigen::Vector3d> crossings(const std::vector<Eigen::Vector3d>& loop, Coordinate coordinate, double level) {
  std::vector<Eigen::Vector3d> points;
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& p = loop[i];
    const Eigen::Vector3d& q = loop[(i + 1) % n];
    const double a = coordinate(p) - level, b = coordinate(q) - level;
    if ((a < 0.0) == (b < 0.0)) continue;  // the half-open rule counts a vertex on the level once
    points.push_back(p + (q - p) * (a / (a - b)));
  }
  return points;
}

// The parameter s in [0, 1] where |p + s (q - p) - centre| = radius, for p inside the sphere and q outside.
double sphere_exit(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& centre, double radius) {
  const Eigen::Vector3d d = q - p, m = p - centre;
  const double a = d.squaredNorm(), b = m.dot(d), c = m.squaredNorm() - radius * radius;  // c <= 0
  if (!(a > 0.0)) return 0.0;
  return std::clamp((-b + std::sqrt(std::max(0.0, b * b - a * c))) / a, 0.0, 1.0);
}

Eigen::Vector3d second_toe_point(const std::vector<Eigen::Vector3d>& lower, const ExpertSplitOptions& options,
                                 FootSide side) {
  double x_back = lower.front().x(), x_front = x_back;
  for (const Eigen::Vector3d& p : lower) {
    x_back = std::min(x_back, p.x());
    x_front = std::max(x_front, p.x());
  }
  const double x_section = x_back + options.toe_section_fraction * (x_front - x_back);
  const std::vector<Eigen::Vector3d> across = crossings(lower, [](const Eigen::Vector3d& p) { return p.x(); }, x_section);
  if (across.size() < 2) throw EngineError("the feather line does not cross the toe box section: cannot mark the second toe");
  const double medial = medial_y_sign(side);
  double y_medial = across.front().y(), y_lateral = y_medial;
  for (const Eigen::Vector3d& p : across) {
    if (medial * p.y() > medial * y_medial) y_medial = p.y();
    if (medial * p.y() < medial * y_lateral) y_lateral = p.y();
  }
  const double y_toe = y_medial + options.second_toe_fraction * (y_lateral - y_medial);
  std::optional<Eigen::Vector3d> front;
  for (const Eigen::Vector3d& p : crossings(lower, [](const Eigen::Vector3d& q) { return q.y(); }, y_toe))
    if (p.x() > x_section && (!front || p.x() > front->x())) front = p;
  if (!front) throw EngineError("the feather line has no toe end on the second toe's line");
  return *front;
}

// The middle of the arc of `lower` whose distance from `toe` is within drop_mm of the largest.
Eigen::Vector3d heel_middle(const std::vector<Eigen::Vector3d>& lower, const Eigen::Vector3d& toe, double drop_mm) {
  const std::size_t n = lower.size();
  std::size_t far = 0;
  for (std::size_t i = 1; i < n; ++i)
    if ((lower[i] - toe).squaredNorm() > (lower[far] - toe).squaredNorm()) far = i;
  const double radius = (lower[far] - toe).norm() - drop_mm;
  auto inside = [&](std::size_t i) { return (lower[i % n] - toe).norm() >= radius; };
  // The arc as a chain of points from its back end to its front end (either way round the loop).
  std::size_t steps_back = 0, steps_ahead = 0;
  while (steps_back + 1 < n && inside(far + n - steps_back - 1)) ++steps_back;
  while (steps_back + steps_ahead + 1 < n && inside(far + steps_ahead + 1)) ++steps_ahead;
  if (steps_back + steps_ahead + 1 >= n) throw EngineError("the feather line has no distinct heel: cannot find the heel middle");
  // The arc's ends lie on the edges leaving it, where the distance falls to `radius`.
  auto end_between = [&](const Eigen::Vector3d& on_arc, const Eigen::Vector3d& off_arc) -> Eigen::Vector3d {
    return off_arc + (on_arc - off_arc) * sphere_exit(off_arc, on_arc, toe, radius);
  };
  const std::size_t first = far + n - steps_back, last = far + n + steps_ahead;
  std::vector<Eigen::Vector3d> arc;
  arc.push_back(end_between(lower[first % n], lower[(first - 1) % n]));
  for (std::size_t i = first; i <= last; ++i) arc.push_back(lower[i % n]);
  arc.push_back(end_between(lower[last % n], lower[(last + 1) % n]));
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < arc.size(); ++i) length += (arc[i + 1] - arc[i]).norm();
  double walked = 0.0;
  for (std::size_t i = 0; i + 1 < arc.size(); ++i) {
    const double step = (arc[i + 1] - arc[i]).norm();
    if (walked + step >= 0.5 * length && step > 0.0) return arc[i] + (arc[i + 1] - arc[i]) * ((0.5 * length - walked) / step);
    walked += step;
  }
  return arc.back();
}

}  // namespace

SplitPlane expert_split_plane(const std::vector<Eigen::Vector3d>& lower, const std::vector<Eigen::Vector3d>& upper,
                              const ExpertSplitOptions& options, FootSide side) {
  if (lower.size() < 3 || upper.size() < 3) throw EngineError("the sole or top contour is too short to place the split plane");
  if (!(options.toe_section_fraction > 0.5 && options.toe_section_fraction < 1.0))
    throw EngineError("the toe box section must lie between 0.5 and 1 of the last's length");
  if (!(options.second_toe_fraction > 0.0 && options.second_toe_fraction < 1.0))
    throw EngineError("the second toe's share of the toe box width must lie between 0 and 1");
  if (!(options.heel_arc_drop_mm > 0.0)) throw EngineError("the heel arc depth must be positive (mm)");
  const Eigen::Vector3d toe = second_toe_point(lower, options, side);
  const Eigen::Vector3d heel = heel_middle(lower, toe, options.heel_arc_drop_mm);
  return plane_through(curve_mean(upper), toe, heel, side);
}

}  // namespace lastcut
