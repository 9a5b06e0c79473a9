// One mark's tool path; see mark_stroke.hpp for which marks are notches.
#include "engine/toolpath/mark_stroke.hpp"

#include <array>

namespace lastcut {

bool is_landmark_mark(const std::string& name) {
  static constexpr std::array<const char*, 4> kLandmarks = {"toe", "heel", "top_front", "top_back"};
  for (const char* landmark : kLandmarks)
    if (name == landmark) return true;
  return false;
}

std::vector<Point2> mark_stroke(const PlacedMark& mark, const NotchOptions& notch) {
  const Point2 along = mark.to_mm - mark.from_mm;
  const double length_mm = along.norm();
  if (!(length_mm >= 1e-6)) return {};
  if (notch.shape == NotchShape::Slit || is_landmark_mark(mark.name)) return {mark.from_mm, mark.to_mm};
  const Point2 across = Point2(-along.y(), along.x()) / length_mm;
  const Point2 half = 0.5 * notch.v_width_mm * across;
  return {mark.from_mm - half, mark.to_mm, mark.from_mm + half};
}

}  // namespace lastcut
