#pragma once
// How far two outlines are apart, once aligned: both outlines are sampled densely (every
// sample_step_mm along each edge, vertices included) and each sample's distance to the other
// outline is measured exactly, point to segment.
//   hausdorff_mm  max over both directions (the symmetric Hausdorff distance, up to the sampling:
//                 the true value is at most sample_step_mm / 2 larger)
//   mean_mm       mean over all samples of both outlines
//   along_mold    per sample of the mold's edge: its signed distance, + where the mold lies
//                 outside the reference (mold too large there), - inside
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

struct EdgeDeviation {
  Point2 at_mm = Point2::Zero();  // sample on the mold's edge
  double signed_mm = 0.0;
};

struct OutlineDeviation {
  double hausdorff_mm = 0.0;
  double mean_mm = 0.0;
  double mold_to_reference_max_mm = 0.0;  // the two directed Hausdorff distances
  double reference_to_mold_max_mm = 0.0;
  std::vector<EdgeDeviation> along_mold;
};

// mold, reference: closed polygons (mm, #P >= 3) in the same frame (reference already moved).
OutlineDeviation outline_deviation(const Polygon2& mold, const Polygon2& reference, double sample_step_mm = 0.25);

// Winding-number test; points on the edge count as either.
bool inside_polygon(const Polygon2& polygon, const Point2& point);

// Distance (mm) from a point to the closed outline (brute force over the edges).
double distance_to_outline(const Polygon2& polygon, const Point2& point);

}  // namespace lastcut
