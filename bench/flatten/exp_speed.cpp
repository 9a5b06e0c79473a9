// temporary experiment (not committed)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include "engine/flatten/arap_iterations.hpp"
#include "engine/flatten/boundary_first_start.hpp"
#include "engine/flatten/plane_rotation_start.hpp"
#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/flatten.hpp"
#include "engine/flatten/lattice_subspace.hpp"
#include "engine/flatten/untangle.hpp"
#include "tests/flatten/flatten_fixtures.hpp"
using namespace lastcut;
using Clock = std::chrono::steady_clock;
static double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
Eigen::MatrixXd outline_of(const Eigen::MatrixXd& UV, const std::vector<int>& loop) {
  Eigen::MatrixXd o(loop.size(), 2);
  for (size_t i = 0; i < loop.size(); ++i) o.row(i) = UV.row(loop[i]);
  return o;
}
int main(int argc, char** argv) {
  TriMesh mesh = testing::read_off(argv[1], 1.0);
  const int cells = std::atoi(argv[2]);
  const int coarse_block = std::atoi(argv[3]);  // subspace iterations per cycle
  const int fine_block = std::atoi(argv[4]);    // full iterations per cycle
  const int cycles = std::atoi(argv[5]);
  const bool plane = argc > 6 && argv[6][0] == 'p';
  FlattenOptions ref; ref.lattice_cells = 0; ref.relative_energy_tolerance = 1e-12; ref.max_iterations = 3000;
  const FlattenResult conv = flatten(mesh, ref);
  const MeshTopology topo = check_disk(mesh);
  const auto& loop = topo.boundary_loops[0];
  const Eigen::MatrixXd target = outline_of(conv.UV, loop);
  std::printf("converged: %d it E=%.6f\n", conv.iterations, conv.energy_final);
  auto t = Clock::now();
  const TriangleFrames frames = compute_triangle_frames(mesh);
  ReducedLaplacian lap = pinned_cotangent_laplacian(frames, topo);
  SparseCholesky factor; factor.analyze_pattern(lap.matrix);
  std::printf("frames+pattern+analyse %.3f\n", since(t)); t = Clock::now();
  Eigen::MatrixXd UV;
  if (!plane) {
    UV = boundary_first_start(mesh, frames, topo, lap, factor);
    std::vector<char> fixed(mesh.V.rows(), 0); fixed[lap.pinned] = 1;
    assemble_laplacian(frames, frames.half_weight, fixed, lap);
  }
  factor.factorize(lap.matrix);
  if (plane) UV = *plane_rotation_start(mesh, frames, topo, lap, factor);
  std::printf("start+factor %.3f\n", since(t)); t = Clock::now();
  LatticeSubspace sub(mesh, lap, lattice_cell_mm(frames.area_mm2.sum(), cells));
  std::printf("lattice %d nodes %.3f\n", sub.node_count(), since(t));
  auto report = [&](const char* what, int it, double E, double s) {
    std::printf("%s it %d E %.6f outline max %.4f rms %.4f  (%.3f s)\n", what, it, E,
                testing::max_distance_after_rigid_alignment(outline_of(UV, loop), target),
                testing::rms_distance_after_rigid_alignment(outline_of(UV, loop), target), s);
  };
  report("start", 0, 0, 0);
  const int early = std::getenv("EARLY") ? std::atoi(std::getenv("EARLY")) : 0;
  if (early > 0) {
    auto f = run_arap_iterations(frames, lap, factor, UV, early, 0.0, false);
    report("early", f.iterations, f.energy_final, 0);
    int before = count_flipped_triangles(mesh.F, UV);
    auto u = untangle_flips(frames, topo, UV);
    std::printf("untangle %d -> %d\n", before, u.flipped_after);
  }
  for (int c = 0; c < cycles; ++c) {
    t = Clock::now();
    auto r = run_arap_subspace_iterations(frames, lap, sub, UV, coarse_block, 0.0);
    double s1 = since(t);
    report(" sub", r.iterations, r.energy_final, s1);
    t = Clock::now();
    auto f = run_arap_iterations(frames, lap, factor, UV, fine_block, 0.0, false);
    report("full", f.iterations, f.energy_final, since(t));
    std::printf("   rejected %d flips %d\n", f.rejected_accelerations, count_flipped_triangles(mesh.F, UV));
  }
}
