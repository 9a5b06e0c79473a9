#pragma once
// The automatic split plane (thesis section 3.1) against the expert's (section 2.1) on generated lasts:
// per last, the angle between the planes, the agreement of the two segmentations
// (engine/segment/segmentation_agreement.hpp) and ARAP's D_angle of each half under both.
// Figures and the command: docs/segmentation-expert.md.

namespace lastcut::bench {

// Prints a markdown table, one row per generated last (EU 36-47, left and right, 0.2 mm noise).
void print_split_agreement();

}  // namespace lastcut::bench
