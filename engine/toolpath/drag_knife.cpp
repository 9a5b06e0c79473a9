#include "engine/toolpath/drag_knife.hpp"

#include <cmath>
#include <numbers>

#include "engine/toolpath/planar_geometry.hpp"

namespace lastcut {
namespace {

// Points of the arc of radius r around `center` from direction `from` turning by turn_rad,
// excluding the start, including the end.
void append_swivel(std::vector<Point2>& holder, const Point2& center, const Point2& from, double turn_rad,
                   double radius_mm, double step_rad) {
  const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(turn_rad) / step_rad)));
  const double start_rad = std::atan2(from.y(), from.x());
  for (int s = 1; s <= steps; ++s) {
    const double angle = start_rad + turn_rad * s / steps;
    holder.push_back(center + radius_mm * Point2(std::cos(angle), std::sin(angle)));
  }
}

}  // namespace

std::vector<Point2> compensate_drag_knife(const std::vector<Point2>& tip_path_mm,
                                          const std::optional<Point2>& incoming_direction,
                                          const DragKnifeOptions& options) {
  const std::vector<Point2> tip = without_repeated_points(tip_path_mm, 1e-6, false);
  const double d = options.blade_offset_mm;
  if (d <= 0.0 || tip.size() < 2) return tip;
  const double threshold_rad = options.corner_threshold_deg * std::numbers::pi / 180.0;
  const double step_rad = options.arc_step_deg * std::numbers::pi / 180.0;

  std::vector<Point2> holder;
  Point2 direction = (tip[1] - tip[0]).normalized();
  if (incoming_direction && incoming_direction->norm() > 0.0) {
    const Point2 incoming = incoming_direction->normalized();
    holder.push_back(tip[0] + d * incoming);
    const double turn = signed_turn_rad(incoming, direction);
    if (std::abs(turn) > threshold_rad) {
      append_swivel(holder, tip[0], incoming, turn, d, step_rad);
    } else {
      holder.push_back(tip[0] + d * direction);
    }
  } else {
    holder.push_back(tip[0] + d * direction);
  }
  for (size_t k = 0; k + 1 < tip.size(); ++k) {
    direction = (tip[k + 1] - tip[k]).normalized();
    holder.push_back(tip[k + 1] + d * direction);
    if (k + 2 < tip.size()) {
      const Point2 next = (tip[k + 2] - tip[k + 1]).normalized();
      const double turn = signed_turn_rad(direction, next);
      if (std::abs(turn) > threshold_rad) append_swivel(holder, tip[k + 1], direction, turn, d, step_rad);
    }
  }
  return without_repeated_points(holder, 1e-6, false);
}

std::vector<Point2> simulate_drag_knife_tip(const std::vector<Point2>& holder_path_mm, const Point2& tip_start_mm,
                                            double blade_offset_mm, double step_mm) {
  std::vector<Point2> tips;
  Point2 tip = tip_start_mm;
  for (size_t k = 0; k + 1 < holder_path_mm.size(); ++k) {
    const Point2 a = holder_path_mm[k], b = holder_path_mm[k + 1];
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step_mm)));
    for (int s = 1; s <= steps; ++s) {
      const Point2 holder = a + (b - a) * (static_cast<double>(s) / steps);
      const Point2 trail = tip - holder;
      // The blade is dragged: it stays blade_offset_mm behind the holder, on the line to where it was.
      if (trail.norm() > 1e-12) tip = holder + blade_offset_mm * trail.normalized();
      tips.push_back(tip);
    }
  }
  return tips;
}

}  // namespace lastcut
