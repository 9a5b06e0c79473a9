// See split_agreement.hpp.
#include "bench/flatten/split_agreement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>

#include "engine/flatten/flatten.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/segment/segmentation_agreement.hpp"

namespace lastcut::bench {
namespace {

double d_angle(const Segment& half) { return measure_distortion(half.mesh, flatten(half.mesh, half.topology).UV).D_angle; }

}  // namespace

void print_split_agreement() {
  std::printf("## Automatic (thesis 3.1) vs expert (thesis 2.1) split plane, generated lasts of 60,000 triangles, "
              "0.2 mm noise\n\n"
              "| last | angle between planes deg | medial cm2 auto / expert | agreement %% | "
              "D_angle auto medial / lateral | D_angle expert medial / lateral |\n|---|---|---|---|---|---|\n");
  double sum = 0.0, lowest = 100.0;
  int count = 0;
  for (int size : {36, 39, 42, 45, 47})
    for (FootSide side : {FootSide::Left, FootSide::Right}) {
      LastParams params = LastParams::for_eu_size(size, side);
      params.surface = LastSurface::Remeshed;  // the figures in docs/ were measured on it
      params.target_triangles = 60000;
      params.noise_mm = 0.2;
      params.seed = static_cast<std::uint64_t>(size);
      // Generated lasts are in the canonical frame already: no orientation step.
      const OrientedLast last{generate_last(params).mesh, Eigen::Affine3d::Identity(), side, {}};
      SegmentOptions expert_options;
      expert_options.split_rule = SplitRule::Expert;
      const BandCut band = cut_band(last, expert_options);
      const SplitPlane automatic_plane = place_split_plane(band, SegmentOptions{});
      const SplitPlane expert_plane = place_split_plane(band, expert_options);
      const Segmentation automatic = split_band(band, automatic_plane), expert = split_band(band, expert_plane);
      const SplitAgreement agreement = split_agreement(band, automatic_plane, expert_plane);
      const double angle_deg =
          std::acos(std::min(1.0, automatic_plane.normal.dot(expert_plane.normal))) * 180.0 / std::numbers::pi;
      std::printf("| EU %d %s | %.2f | %.1f / %.1f | **%.2f** | %.4f / %.4f | %.4f / %.4f |\n", size,
                  std::string(to_string(side)).c_str(), angle_deg, agreement.medial_a_mm2 / 100.0,
                  agreement.medial_b_mm2 / 100.0, agreement.percent(), d_angle(automatic.medial),
                  d_angle(automatic.lateral), d_angle(expert.medial), d_angle(expert.lateral));
      std::fflush(stdout);
      sum += agreement.percent();
      lowest = std::min(lowest, agreement.percent());
      ++count;
    }
  std::printf("\nAgreement over %d lasts: mean %.2f %%, lowest %.2f %%\n", count, sum / count, lowest);
}

}  // namespace lastcut::bench
