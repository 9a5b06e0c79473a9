// See convergence_quality.hpp.
#include "bench/flatten/convergence_quality.hpp"

#include <algorithm>
#include <cstdio>

#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/flatten.hpp"
#include "tests/flatten/flatten_fixtures.hpp"

namespace lastcut::bench {
namespace {

FlattenResult fully_converged(const TriMesh& mesh) {
  FlattenOptions options;
  options.max_iterations = 3000;
  options.relative_energy_tolerance = 1e-12;
  return flatten(mesh, options);
}

// Outline (boundary loop) vertices of UV, #loop x 2, mm.
Eigen::MatrixXd outline_of(const Eigen::MatrixXd& UV, const std::vector<int>& loop) {
  Eigen::MatrixXd outline(static_cast<Eigen::Index>(loop.size()), 2);
  for (size_t i = 0; i < loop.size(); ++i) outline.row(static_cast<Eigen::Index>(i)) = UV.row(loop[i]);
  return outline;
}

double median_of(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

void print_convergence_quality(const std::vector<BenchHalf>& halves, int runs) {
  std::printf("\n## Speed and quality: default flatten() against the fully converged map (%d runs)\n\n"
              "| half | triangles | flatten min s | median s | init s | factorize s (count) | iterations | "
              "outline max mm | outline rms mm | D_angle | D_area | converged D_angle | converged D_area | "
              "converged iterations | flipped |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
              runs);
  for (const BenchHalf& half : halves) {
    std::vector<double> seconds;
    FlattenResult fastest;
    for (int run = 0; run < runs; ++run) {
      FlattenResult result = flatten(half.mesh);
      seconds.push_back(result.seconds_total);
      if (run == 0 || result.seconds_total < fastest.seconds_total) fastest = std::move(result);
    }
    const FlattenResult converged = fully_converged(half.mesh);
    const std::vector<int> loop = check_disk(half.mesh).boundary_loops[0];
    const Eigen::MatrixXd outline = outline_of(fastest.UV, loop), target = outline_of(converged.UV, loop);
    const DistortionMeasures d = measure_distortion(half.mesh, fastest.UV);
    const DistortionMeasures dc = measure_distortion(half.mesh, converged.UV);
    std::printf("| %s | %d | **%.3f** | %.3f | %.3f | %.3f (%d) | %d | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | "
                "%d%s | %d |\n",
                half.name.c_str(), half.mesh.triangle_count(), *std::min_element(seconds.begin(), seconds.end()),
                median_of(seconds), fastest.seconds_init, fastest.seconds_factorize, fastest.factorizations,
                fastest.iterations, testing::max_distance_after_rigid_alignment(outline, target),
                testing::rms_distance_after_rigid_alignment(outline, target), d.D_angle, d.D_area, dc.D_angle,
                dc.D_area, converged.iterations, converged.converged ? "" : " (limit)", d.flipped_triangles);
    std::fflush(stdout);
  }
}

void print_outline_by_iteration(const std::vector<BenchHalf>& halves) {
  std::printf("\n## Outline distance to the converged map after exactly k iterations (no energy tolerance; then the "
              "default fold repair)\n\n"
              "| half | k | outline max mm | outline rms mm | D_angle | D_area | flipped |\n"
              "|---|---|---|---|---|---|---|\n");
  for (const BenchHalf& half : halves) {
    const FlattenResult converged = fully_converged(half.mesh);
    const std::vector<int> loop = check_disk(half.mesh).boundary_loops[0];
    const Eigen::MatrixXd target = outline_of(converged.UV, loop);
    // Up to the iteration count a mold cut to 0.1 mm needs (the first k within 0.05 mm ends the rows).
    constexpr double kWithinMm = 0.05;
    for (int k = 5; k <= 120; k += 5) {
      FlattenOptions options;
      options.max_iterations = k;
      options.relative_energy_tolerance = 0.0;
      const FlattenResult r = flatten(half.mesh, options);
      const Eigen::MatrixXd outline = outline_of(r.UV, loop);
      const DistortionMeasures d = measure_distortion(half.mesh, r.UV);
      const double max_mm = testing::max_distance_after_rigid_alignment(outline, target);
      std::printf("| %s | %d | %.4f | %.4f | %.4f | %.4f | %d |\n", half.name.c_str(), k, max_mm,
                  testing::rms_distance_after_rigid_alignment(outline, target), d.D_angle, d.D_area,
                  d.flipped_triangles);
      std::fflush(stdout);
      if (max_mm <= kWithinMm) break;
    }
  }
}

}  // namespace lastcut::bench
