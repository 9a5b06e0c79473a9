#include "engine/mold/balance_notches.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/engine_error.hpp"

namespace lastcut {

namespace {

void check_spacing(double spacing_mm, const char* edge) {
  if (spacing_mm == 0.0) return;
  if (!std::isfinite(spacing_mm) || !(spacing_mm >= kMinBalanceSpacing_mm))
    throw EngineError(std::string("balance notch spacing along the ") + edge + " must be 0 (off) or at least " +
                      std::to_string(static_cast<int>(kMinBalanceSpacing_mm)) + " mm");
}

double open_length_mm(const std::vector<Point2>& polyline) {
  double length = 0.0;
  for (size_t i = 1; i < polyline.size(); ++i) length += (polyline[i] - polyline[i - 1]).norm();
  return length;
}

}  // namespace

PolylinePoint point_at_arc_length(const std::vector<Point2>& polyline, double s_mm) {
  PolylinePoint at;
  if (polyline.empty()) return at;
  at.point = s_mm <= 0.0 ? polyline.front() : polyline.back();
  double walked = 0.0;
  for (size_t i = 1; i < polyline.size(); ++i) {
    const Point2 step = polyline[i] - polyline[i - 1];
    const double length = step.norm();
    if (length == 0.0) continue;
    at.direction = step / length;
    if (s_mm > 0.0 && walked + length >= s_mm) {
      at.point = polyline[i - 1] + std::clamp((s_mm - walked) / length, 0.0, 1.0) * step;
      return at;
    }
    if (s_mm <= 0.0) return at;
    walked += length;
  }
  return at;
}

std::vector<NetNotch> balance_notch_points(const std::vector<NetEdge>& edges, const BalanceNotches& spacing) {
  check_spacing(spacing.seam_spacing_mm, "centre cut");
  check_spacing(spacing.feather_spacing_mm, "feather line");
  std::vector<NetNotch> notches;
  for (const NetEdge& edge : edges) {
    double spacing_mm = 0.0;
    const char* start = "";
    std::string prefix;
    switch (edge.kind) {
      case EdgeKind::FrontSeam: spacing_mm = spacing.seam_spacing_mm, start = "toe", prefix = "balance_seam_front_"; break;
      case EdgeKind::BackSeam: spacing_mm = spacing.seam_spacing_mm, start = "heel", prefix = "balance_seam_back_"; break;
      case EdgeKind::Feather: spacing_mm = spacing.feather_spacing_mm, start = "heel", prefix = "balance_feather_"; break;
      case EdgeKind::Top: break;
    }
    if (spacing_mm <= 0.0) continue;
    std::vector<Point2> line = edge.points;
    const bool reversed = edge.from != start;
    if (reversed) std::reverse(line.begin(), line.end());
    const double length_mm = open_length_mm(line);
    for (int k = 1; k * spacing_mm <= length_mm - 0.5 * spacing_mm; ++k) {
      const double s_mm = k * spacing_mm;
      const PolylinePoint at = point_at_arc_length(line, s_mm);
      // The net runs counter-clockwise, so outside is to the right of its direction.
      const Point2 along = reversed ? Point2(-at.direction) : at.direction;
      notches.push_back({prefix + std::to_string(k), at.point, s_mm, Point2(along.y(), -along.x())});
    }
  }
  return notches;
}

}  // namespace lastcut
