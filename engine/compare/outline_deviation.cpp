#include "engine/compare/outline_deviation.hpp"

#include <algorithm>
#include <limits>

#include "engine/core/engine_error.hpp"
#include "engine/mold/outline_alignment.hpp"

namespace lastcut {

bool inside_polygon(const Polygon2& polygon, const Point2& point) {
  int winding = 0;
  const auto& p = polygon.points;
  for (size_t i = 0; i < p.size(); ++i) {
    const Point2& a = p[i];
    const Point2& b = p[(i + 1) % p.size()];
    const double side = (b.x() - a.x()) * (point.y() - a.y()) - (point.x() - a.x()) * (b.y() - a.y());
    if (a.y() <= point.y()) {
      if (b.y() > point.y() && side > 0.0) ++winding;
    } else if (b.y() <= point.y() && side < 0.0) {
      --winding;
    }
  }
  return winding != 0;
}

double distance_to_outline(const Polygon2& polygon, const Point2& point) {
  double best = std::numeric_limits<double>::infinity();
  const auto& p = polygon.points;
  for (size_t i = 0; i < p.size(); ++i) best = std::min(best, distance_to_segment(point, p[i], p[(i + 1) % p.size()]));
  return best;
}

OutlineDeviation outline_deviation(const Polygon2& mold, const Polygon2& reference, double sample_step_mm) {
  if (mold.points.size() < 3 || reference.points.size() < 3) throw EngineError("outline deviation needs two outlines");
  if (!(sample_step_mm > 0.0)) throw EngineError("outline deviation needs a sampling step > 0 mm");
  OutlineDeviation result;
  double sum = 0.0;
  const std::vector<Point2> mold_samples = sample_outline(mold, sample_step_mm);
  result.along_mold.reserve(mold_samples.size());
  for (const auto& p : mold_samples) {
    const double d = distance_to_outline(reference, p);
    result.mold_to_reference_max_mm = std::max(result.mold_to_reference_max_mm, d);
    sum += d;
    result.along_mold.push_back({p, inside_polygon(reference, p) ? -d : d});
  }
  const std::vector<Point2> reference_samples = sample_outline(reference, sample_step_mm);
  for (const auto& p : reference_samples) {
    const double d = distance_to_outline(mold, p);
    result.reference_to_mold_max_mm = std::max(result.reference_to_mold_max_mm, d);
    sum += d;
  }
  result.hausdorff_mm = std::max(result.mold_to_reference_max_mm, result.reference_to_mold_max_mm);
  result.mean_mm = sum / static_cast<double>(mold_samples.size() + reference_samples.size());
  return result;
}

}  // namespace lastcut
