#pragma once
// A mold-like outline with four sharp corners (heel, toe, top_front, top_back) joined by curved
// edges sampled every ~0.5 mm, as a flattened last half looks: about 270 x 110 mm, no symmetry.
#include <cmath>
#include <numbers>
#include <string>

#include "engine/mold/mold.hpp"

namespace lastcut::testing {

inline Point2 quadratic(const Point2& a, const Point2& c, const Point2& b, double t) {
  return (1 - t) * (1 - t) * a + 2 * (1 - t) * t * c + t * t * b;
}

// Counter-clockwise: heel -> toe along the sole edge, up the toe curve to top_front, along the top
// line to top_back, down the heel curve.
inline Mold synthetic_mold() {
  const Point2 heel(0, 0), toe(262, 12), top_front(172, 96), top_back(28, 104);
  const Point2 controls[4] = {{130, -30}, {250, 70}, {110, 60}, {-22, 48}};
  const Point2 corners[5] = {heel, toe, top_front, top_back, heel};
  Mold mold;
  mold.name = "synthetic";
  for (int edge = 0; edge < 4; ++edge) {
    const int pieces = static_cast<int>(std::ceil((corners[edge + 1] - corners[edge]).norm() / 0.5));
    for (int k = 0; k < pieces; ++k)
      mold.outline.points.push_back(quadratic(corners[edge], controls[edge], corners[edge + 1],
                                              static_cast<double>(k) / pieces));
  }
  const char* names[4] = {"heel", "toe", "top_front", "top_back"};
  for (int c = 0; c < 4; ++c) mold.marks.push_back({names[c], corners[c], Point2::Zero()});
  return mold;
}

}  // namespace lastcut::testing
