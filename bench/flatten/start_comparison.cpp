// See start_comparison.hpp.
#include "bench/flatten/start_comparison.hpp"

#include <cstdio>

#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/flatten.hpp"
#include "tests/flatten/flatten_fixtures.hpp"

namespace lastcut::bench {

void print_start_comparison(const std::vector<BenchHalf>& halves) {
  std::printf("\n## ARAP start maps (same halves, same run; outline distance to the converged map)\n\n"
              "| half | triangles | start | iterations | total s | final energy mm^2 | converged-map energy mm^2 | "
              "outline max mm | outline rms mm | flipped |\n|---|---|---|---|---|---|---|---|---|---|\n");
  for (const BenchHalf& half : halves) {
    FlattenOptions converged_options;
    converged_options.max_iterations = 2000;
    converged_options.relative_energy_tolerance = 1e-12;
    const FlattenResult converged = flatten(half.mesh, converged_options);
    const MeshTopology topology = check_disk(half.mesh);
    const std::vector<int>& loop = topology.boundary_loops[0];
    Eigen::MatrixXd converged_outline(static_cast<Eigen::Index>(loop.size()), 2);
    for (size_t i = 0; i < loop.size(); ++i) converged_outline.row(static_cast<Eigen::Index>(i)) = converged.UV.row(loop[i]);
    for (ArapStart start : {ArapStart::BoundaryFirst, ArapStart::PlaneRotation}) {
      FlattenOptions options;
      options.start = start;
      FlattenResult best;
      for (int repeat = 0; repeat < 3; ++repeat) {
        FlattenResult result = flatten(half.mesh, options);
        if (repeat == 0 || result.seconds_total < best.seconds_total) best = std::move(result);
      }
      Eigen::MatrixXd outline(static_cast<Eigen::Index>(loop.size()), 2);
      for (size_t i = 0; i < loop.size(); ++i) outline.row(static_cast<Eigen::Index>(i)) = best.UV.row(loop[i]);
      const double max_mm = testing::max_distance_after_rigid_alignment(outline, converged_outline);
      const double rms_mm = testing::rms_distance_after_rigid_alignment(outline, converged_outline);
      std::printf("| %s | %d | %s | %d | %.3f | %.2f | %.2f | %.3f | %.3f | %d |\n", half.name.c_str(),
                  half.mesh.triangle_count(), start == ArapStart::BoundaryFirst ? "boundary-first" : "plane rotation",
                  best.iterations, best.seconds_total, best.energy_final, converged.energy_final, max_mm, rms_mm,
                  best.flipped_triangles);
      std::fflush(stdout);
    }
  }
}

}  // namespace lastcut::bench
