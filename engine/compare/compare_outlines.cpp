#include "engine/compare/compare_outlines.hpp"

#include <algorithm>

namespace lastcut {

double Comparison::max_margin_mm() const {
  double largest = 0.0;
  for (const auto& corner : corners) largest = std::max(largest, corner.margin_mm);
  return largest;
}

Comparison compare_mold(const Mold& mold, const Mold& reference, const CompareOptions& options) {
  Comparison result;
  result.mold = mold;
  result.alignment = align_for_overlap(reference.outline, mold.outline, options.overlap);
  const PlaneMotion& motion = result.alignment.motion;
  result.reference_moved.name = reference.name;
  result.reference_moved.outline = moved(reference.outline, motion);
  for (const auto& mark : reference.marks) {
    MoldMark m = mark;
    m.position_mm = motion.apply(mark.position_mm);
    // A direction moves without the translation.
    m.inward_direction = motion.apply(mark.inward_direction) - motion.apply(Point2::Zero());
    result.reference_moved.marks.push_back(m);
  }
  result.corners = match_corners(mold, result.reference_moved, options.corners);
  result.deviation = outline_deviation(mold.outline, result.reference_moved.outline, options.deviation_step_mm);
  return result;
}

std::vector<CornerMatch> corners_beyond(const Comparison& comparison, double tolerance_mm) {
  std::vector<CornerMatch> beyond;
  for (const auto& corner : comparison.corners)
    if (corner.margin_mm > tolerance_mm) beyond.push_back(corner);
  std::sort(beyond.begin(), beyond.end(), [](const auto& a, const auto& b) { return a.margin_mm > b.margin_mm; });
  return beyond;
}

}  // namespace lastcut
