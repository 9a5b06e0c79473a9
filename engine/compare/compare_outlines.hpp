#pragma once
// A mold checked against a reference pattern: the reference moved onto the mold for the largest
// overlap (rigid_overlap_alignment), the corner margins (outline_corners) and the outline
// deviation (outline_deviation), all in the mold's frame, mm.
#include <string>
#include <vector>

#include "engine/compare/outline_corners.hpp"
#include "engine/compare/outline_deviation.hpp"
#include "engine/compare/rigid_overlap_alignment.hpp"
#include "engine/mold/mold.hpp"

namespace lastcut {

struct CompareOptions {
  OverlapOptions overlap;
  CornerOptions corners;
  double deviation_step_mm = 0.25;
};

struct Comparison {
  Mold mold;                // as given
  Mold reference_moved;     // the reference (outline and marks) after alignment.motion
  OverlapAlignment alignment;
  std::vector<CornerMatch> corners;
  OutlineDeviation deviation;
  // Largest corner margin (mm); 0 without corners.
  double max_margin_mm() const;
};

// Throws EngineError when either outline has no area.
Comparison compare_mold(const Mold& mold, const Mold& reference, const CompareOptions& options = {});

// The corners whose margin exceeds tolerance_mm, largest first.
std::vector<CornerMatch> corners_beyond(const Comparison& comparison, double tolerance_mm);

}  // namespace lastcut
