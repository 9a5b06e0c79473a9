#pragma once
// The limits of the mold quality gate (mold_quality_gate.hpp), a plain struct so that the daemon's
// configuration ([quality], docs/quality-gate.md) can hold them without linking the engine.
// Defaults: every good scan in the test data passes. Generated lasts flatten with D_angle and D_area
// below 2.02 (2 is ideal) up to 0.3 mm of scanner noise; the FIND foot's half (toes: far from
// developable) gives D_angle 2.11, D_area 2.13, max stretch 4.7, p95 1.34; its 100k-triangle
// subdivision 6.1 after the flip repair. The molds the gate
// exists for (an outline that crossed itself, a fallback that stopped early) have D_angle 3-4, a
// max stretch near 15, no convergence and a span 10-30 % longer than the surface.

namespace lastcut {

struct MoldQualityLimits {
  double max_D_angle = 2.2;           // thesis eq. (1); 2 is ideal
  double max_D_area = 2.2;            // thesis eq. (2)
  double max_stretch = 8.0;           // largest sigma1 of any triangle
  double max_p95_stretch = 1.5;       // 95th percentile of sigma1
  bool require_converged = true;      // ARAP reached its energy tolerance
  double max_length_excess_pct = 5.0; // mold span against the path along the surface
};

}  // namespace lastcut
