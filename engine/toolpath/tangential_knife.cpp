#include "engine/toolpath/tangential_knife.hpp"

#include <cmath>
#include <numbers>

#include "engine/toolpath/planar_geometry.hpp"

namespace lastcut {

double unwrap_near(double direction_deg, double reference_deg) {
  return reference_deg + std::remainder(direction_deg - reference_deg, 360.0);
}

std::vector<Stroke> split_for_tangential_knife(const Stroke& stroke, double corner_threshold_deg,
                                               double& current_angle_deg) {
  const std::vector<Point2> points = without_repeated_points(stroke.points_mm, 1e-6, false);
  std::vector<Stroke> pieces;
  if (points.size() < 2) return pieces;
  auto start_stroke = [&](const Point2& at, double angle_deg) {
    Stroke next;
    next.tool = stroke.tool;
    next.piece = stroke.piece;
    next.closed_outline = stroke.closed_outline;
    next.points_mm.push_back(at);
    next.knife_angle_deg.push_back(angle_deg);
    pieces.push_back(std::move(next));
  };
  auto direction_deg = [&](size_t k) {
    const Point2 edge = points[k + 1] - points[k];
    return std::atan2(edge.y(), edge.x()) * 180.0 / std::numbers::pi;
  };
  double angle_deg = unwrap_near(direction_deg(0), current_angle_deg);
  start_stroke(points[0], angle_deg);
  for (size_t k = 0; k + 1 < points.size(); ++k) {
    Stroke& active = pieces.back();
    active.points_mm.push_back(points[k + 1]);
    active.knife_angle_deg.push_back(angle_deg);
    if (k + 2 >= points.size()) break;
    const double next_deg = unwrap_near(direction_deg(k + 1), angle_deg);
    if (std::abs(next_deg - angle_deg) > corner_threshold_deg) {
      start_stroke(points[k + 1], next_deg);  // lift, turn in the air, plunge
    } else if (next_deg != angle_deg) {
      active.points_mm.push_back(points[k + 1]);  // turn in place, knife down
      active.knife_angle_deg.push_back(next_deg);
    }
    angle_deg = next_deg;
  }
  current_angle_deg = angle_deg;
  return pieces;
}

}  // namespace lastcut
