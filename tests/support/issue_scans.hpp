#pragma once
// Scans that issues describe, built with the generator so that tests meet exactly the case reported.
#include "engine/lastgen/last_params.hpp"

namespace lastcut::test {

// Issue 36's scan: a right EU 41 last, lofted (rings, slivers at the heel and toe poles), 90k
// triangles, every vertex moved by 0.2 mm of Gaussian noise in all three directions, random pose.
// Uncleaned, its medial mold came out about 400 mm long with D_angle 4.
inline LastParams lofted_noisy_scan_of_issue_36() {
  LastParams params = LastParams::for_eu_size(41, FootSide::Right);
  params.surface = LastSurface::Lofted;
  params.target_triangles = 90000;
  params.noise_mm = 0.2;
  params.noise_kind = ScanNoise::Isotropic;
  params.random_pose = true;
  params.seed = 5;
  return params;
}

}  // namespace lastcut::test
