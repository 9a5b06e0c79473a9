#pragma once
// Tangential knives: the blade is turned by a rotary axis so that it always points along the cut.
// Along an edge the angle is constant; at a vertex the blade turns in place, knife down, when the
// turn is at most the corner threshold (leather tolerates a small twist); above it the knife is
// lifted, turned in the air and plunged again (lift-rotate-plunge), so a sharp corner is never
// torn. Angles are unwrapped: they grow past 360 degrees instead of jumping back, so the axis
// always turns the short way and never spins a full turn between two moves.
#include <vector>

#include "engine/toolpath/cut_program.hpp"

namespace lastcut {

// The direction angle (deg) equivalent to direction_deg that is nearest to reference_deg.
double unwrap_near(double direction_deg, double reference_deg);

// Splits a knife stroke (its points_mm, >= 2, no knife_angle_deg yet) at every corner whose turn
// exceeds corner_threshold_deg and gives every point its blade angle. Two equal consecutive points
// encode the in-place turn at a mild corner. current_angle_deg: the axis position before the
// stroke (updated to the last angle). Returns >= 1 strokes with the same tool, piece and flags.
std::vector<Stroke> split_for_tangential_knife(const Stroke& stroke, double corner_threshold_deg,
                                               double& current_angle_deg);

}  // namespace lastcut
