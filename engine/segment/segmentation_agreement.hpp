#pragma once
// How far two lengthwise splits of the same last agree, as a share of surface: the measure behind
// comparing the automatic segmentation with the experts' cut (M. Sabaliauskas, doctoral thesis,
// Vilnius University, 2017, conclusion 1; there 97.85 % came from comparing flattened molds with
// real wax-foil molds by pixel overlap, which this does not reproduce: docs/segmentation-expert.md).
//
// Both splits cut the same band, the surface between the feather line and the top rim (BandCut):
// only the plane differs. With M_A, L_A the medial and lateral halves of split A (and M_B, L_B of B),
//   agreement = 100 (area(M_A ∩ M_B) + area(L_A ∩ L_B)) / area(M_A ∪ L_A ∪ M_B ∪ L_B)   [%]
// where the union is the band. A half is what split_band cuts: the band where the plane's signed
// distance, after the level-set cut's snapping (level_set_cut.hpp), is > 0 (medial) or <= 0
// (lateral); that field is linear on each band triangle, so each triangle's part in M_A ∩ L_B and
// in L_A ∩ M_B is a convex polygon, clipped exactly from the triangle by the two half-planes, and
//   agreement = 100 (1 - (area(M_A ∩ L_B) + area(L_A ∩ M_B)) / area(band)).
// No sampling, no pixels: exact up to rounding, and exactly 100 for a split compared with itself.
// extract_half also drops stray pieces and fills islands of a half; on a last there are none (the
// halves' areas equal medial_a_mm2 and the band minus it, tests/segment).
#include "engine/segment/segment_last.hpp"

namespace lastcut {

struct SplitAgreement {
  double band_area_mm2 = 0;      // area of the band, the union of all four halves
  double disagreement_mm2 = 0;   // area(M_A ∩ L_B) + area(L_A ∩ M_B)
  double medial_a_mm2 = 0;       // area(M_A)
  double medial_b_mm2 = 0;       // area(M_B)
  double percent() const { return 100.0 * (band_area_mm2 - disagreement_mm2) / band_area_mm2; }
};

// band: the last cut along the feather line and top rim (cut_band); a, b: two split planes of it.
// Throws EngineError when the band has no area.
SplitAgreement split_agreement(const BandCut& band, const SplitPlane& a, const SplitPlane& b);

}  // namespace lastcut
