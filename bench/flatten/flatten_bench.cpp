// Flattening benchmark: ARAP on half lasts (init, factorization, per-iteration, total, distortion reached)
// against plain baselines measured in the same run, the sparse Cholesky backends, and LSCM vs ABF++ vs ARAP.
// Usage: bench_flatten [--no-400k] [--arap-only] [--starts] [--methods-only] [--quality RUNS] [--trace]
//                      [--only NAME-PART] [--save FOLDER] [--from FOLDER] | --split-agreement
// Prints markdown tables (docs/benchmarks-flatten.md); --help lists the options.
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "bench/flatten/bench_halves.hpp"
#include "bench/flatten/split_agreement.hpp"
#include "bench/flatten/convergence_quality.hpp"
#include "bench/flatten/start_comparison.hpp"
#include "engine/flatten/arap_iterations.hpp"
#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/flatten.hpp"
#include "engine/flatten/plane_rotation_start.hpp"
#include "engine/flatten/tutte_embedding.hpp"
#include "engine/mesh/write_mesh.hpp"

namespace lastcut::bench {
namespace {

using Clock = std::chrono::steady_clock;

double wall_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// CPU time of this thread: what the flattening itself used, whatever else the shared machine runs.
double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Timed {
  FlattenResult result;
  double cpu_s = 0;
};

Timed timed_flatten(const TriMesh& mesh, const FlattenOptions& options, int repeats) {
  Timed best;
  for (int r = 0; r < repeats; ++r) {
    const double cpu = thread_cpu_s();
    FlattenResult result = flatten(mesh, options);
    const double used = thread_cpu_s() - cpu;
    if (r == 0 || result.seconds_total < best.result.seconds_total) best = {std::move(result), used};
  }
  return best;
}

// The same ARAP (same start map, same Laplacian) done plainly: the Laplacian analysed and factored again
// in every iteration. Returns the seconds per iteration measured over `iterations` iterations.
double refactorizing_seconds_per_iteration(const TriMesh& mesh, int iterations) {
  const MeshTopology topology = check_disk(mesh);
  const TriangleFrames frames = compute_triangle_frames(mesh);
  ReducedLaplacian laplacian = pinned_cotangent_laplacian(frames, topology);
  std::vector<char> fixed(mesh.vertex_count(), 0);  // for the re-assembly in every iteration below
  fixed[laplacian.pinned] = 1;
  Eigen::MatrixXd UV;
  {
    SparseCholesky start_factor;
    start_factor.analyze_pattern(laplacian.matrix);
    start_factor.factorize(laplacian.matrix);
    std::optional<Eigen::MatrixXd> start = plane_rotation_start(mesh, frames, topology, laplacian, start_factor);
    if (!start) {
      ReducedLaplacian tutte_pattern = laplacian;
      start = tutte_embedding(mesh, frames, topology, tutte_pattern, start_factor);
    }
    UV = std::move(*start);
  }
  const auto start = Clock::now();
  for (int i = 0; i < iterations; ++i) {
    assemble_laplacian(frames, frames.half_weight, fixed, laplacian);
    SparseCholesky factor;
    factor.analyze_pattern(laplacian.matrix);
    factor.factorize(laplacian.matrix);
    run_arap_iterations(frames, laplacian, factor, UV, 1, 0.0, false, false);
  }
  return wall_since(start) / iterations;
}

const char* method_name(FlattenMethod method) {
  switch (method) {
    case FlattenMethod::Arap: return "ARAP";
    case FlattenMethod::Lscm: return "LSCM";
    case FlattenMethod::Abf: return "ABF++";
  }
  return "?";
}

void solver_rows(const BenchHalf& half) {
  const MeshTopology topology = check_disk(half.mesh);
  const TriangleFrames frames = compute_triangle_frames(half.mesh);
  ReducedLaplacian laplacian = pinned_cotangent_laplacian(frames, topology);
  const Eigen::MatrixXd rhs = Eigen::MatrixXd::Ones(laplacian.matrix.rows(), 2);
  struct Variant {
    SparseSolver solver;
    FillOrdering ordering;
    const char* ordering_name;
  };
  const Variant variants[] = {
      {SparseSolver::EigenLdlt, FillOrdering::Amd, "AMD"},
      {SparseSolver::CholmodSimplicial, FillOrdering::Amd, "AMD"},
      {SparseSolver::CholmodSimplicial, FillOrdering::NestedDissection, "NESDIS (METIS)"},
      {SparseSolver::CholmodSupernodal, FillOrdering::Amd, "AMD"},
      {SparseSolver::CholmodSupernodal, FillOrdering::NestedDissection, "NESDIS (METIS)"},
      {SparseSolver::Cholmod, FillOrdering::Amd, "AMD"},
  };
  for (const Variant& v : variants) {
    double analyze = 1e9, factorize = 1e9, solve = 1e9;
    for (int repeat = 0; repeat < 3; ++repeat) {
      SparseCholesky factor(v.solver, v.ordering);
      auto t = Clock::now();
      factor.analyze_pattern(laplacian.matrix);
      analyze = std::min(analyze, wall_since(t));
      t = Clock::now();
      factor.factorize(laplacian.matrix);
      factorize = std::min(factorize, wall_since(t));
      t = Clock::now();
      const Eigen::MatrixXd x = factor.solve(rhs);
      solve = std::min(solve, wall_since(t));
      if (!x.allFinite()) std::printf("| solve failed |\n");
    }
    std::printf("| %d | %s | %s | %.3f | %.3f | %.1f |\n", half.mesh.triangle_count(),
                std::string(to_string(v.solver)).c_str(), v.ordering_name, analyze, factorize, 1e3 * solve);
  }
}

// LSCM, ABF++ and ARAP side by side on the halves up to 120k triangles (one run each, wall and CPU s).
void print_method_comparison(const std::vector<BenchHalf>& halves) {
  std::printf("\n## LSCM vs ABF++ vs ARAP (thesis comparison; ABF++ iterations are Newton steps)\n\n| half | triangles | "
              "method | D_angle | D_area | area error %% | boundary error %% | p95 stretch | flipped | iterations | "
              "total s | total CPU s |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::string> method_notes;
  for (const BenchHalf& half : halves) {
    if (half.mesh.triangle_count() > 120000) continue;
    for (FlattenMethod method : {FlattenMethod::Arap, FlattenMethod::Abf, FlattenMethod::Lscm}) {
      FlattenOptions options;
      options.method = method;
      const double cpu = thread_cpu_s();
      const FlattenResult r = flatten(half.mesh, options);
      const double cpu_s = thread_cpu_s() - cpu;
      const DistortionMeasures d = measure_distortion(half.mesh, r.UV);
      std::printf("| %s | %d | %s | %.4f | %.4f | %.2f | %.2f | %.3f | %d | %d | %.3f | %.3f |\n", half.name.c_str(),
                  half.mesh.triangle_count(), method_name(method), d.D_angle, d.D_area,
                  d.area_error_pct, d.boundary_error_pct, d.p95_stretch, d.flipped_triangles, r.iterations,
                  r.seconds_total, cpu_s);
      for (const std::string& note : r.notes)
        method_notes.push_back(half.name + ", " + method_name(method) + ": " + note);
    }
  }
  if (!method_notes.empty()) std::printf("\nNotes:\n");
  for (const std::string& note : method_notes) std::printf("- %s\n", note.c_str());
}

}  // namespace
}  // namespace lastcut::bench

int main(int argc, char** argv) {
  using namespace lastcut;
  using namespace lastcut::bench;
  bool largest = true, arap_only = false, starts = false, methods_only = false, trace = false;
  int quality_runs = 0;  // --quality RUNS: only the speed-and-quality table
  std::string only;         // run only the halves whose name contains this
  std::string save_folder;  // write each half there as <triangles>.off (to profile one half alone)
  std::string from_folder;  // read the halves from there (OFF in mm, as --save wrote them) instead of making them
  bool no_400k = false, split_agreement = false;
  CLI::App app{"Flattening benchmark: ARAP on half lasts against plain baselines, the sparse Cholesky backends, "
               "LSCM vs ABF++ vs ARAP (markdown tables, docs/benchmarks-flatten.md)"};
  app.add_flag("--no-400k", no_400k, "skip the 400k-triangle halves");
  app.add_flag("--arap-only", arap_only, "only the ARAP table");
  app.add_flag("--starts", starts, "only the comparison of start maps");
  app.add_flag("--methods-only", methods_only, "only LSCM vs ABF++ vs ARAP");
  app.add_flag("--trace", trace, "outline distance to the converged map after k iterations");
  app.add_option("--quality", quality_runs, "only the speed-and-quality table, best of RUNS");
  app.add_option("--only", only, "only the halves whose name contains this");
  app.add_option("--save", save_folder, "write each half into this folder as <triangles>.off");
  app.add_option("--from", from_folder, "read the halves from this folder (OFF in mm, as --save wrote them)");
  app.add_flag("--split-agreement", split_agreement, "only the automatic vs expert split table");
  CLI11_PARSE(app, argc, argv);
  largest = !no_400k;
  if (split_agreement) {
    print_split_agreement();
    return 0;
  }
  std::vector<BenchHalf> halves;
  if (!from_folder.empty()) {
    halves = saved_halves(from_folder);
  } else {
    halves = reference_halves(largest);
    for (BenchHalf& foot_half : find_foot_halves(100000)) halves.push_back(std::move(foot_half));
    std::vector<int> generated_sizes = {25000, 100000};
    if (largest) generated_sizes.push_back(400000);
    for (BenchHalf& generated : generated_halves(generated_sizes)) halves.push_back(std::move(generated));
  }
  std::erase_if(halves, [&](const BenchHalf& h) { return h.name.find(only) == std::string::npos; });
  std::sort(halves.begin(), halves.end(),
            [](const BenchHalf& a, const BenchHalf& b) { return a.mesh.triangle_count() < b.mesh.triangle_count(); });
  if (!save_folder.empty()) {
    for (const BenchHalf& half : halves) {
      write_mesh(save_folder + "/" + std::to_string(half.mesh.triangle_count()) + ".off", half.mesh);
    }
  }

  if (quality_runs > 0 || trace) {
    if (quality_runs > 0) print_convergence_quality(halves, quality_runs);
    if (trace) print_outline_by_iteration(halves);
    return 0;
  }
  if (methods_only) {
    print_method_comparison(halves);
    return 0;
  }
  std::printf("## ARAP (default options: boundary-first start, Auto solver = %s, Anderson acceleration, tolerance 1e-6)\n\n",
              std::string(to_string(SparseCholesky().backend())).c_str());
  std::printf("| half | triangles | init s | factorize s (count) | per iteration ms | iterations | total s | "
              "total CPU s | D_angle | D_area | flipped | notes |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<Timed> ours;
  for (const BenchHalf& half : halves) {
    const int repeats = half.mesh.triangle_count() > 200000 ? 1 : 3;
    Timed t = timed_flatten(half.mesh, {}, repeats);
    const FlattenResult& r = t.result;
    const DistortionMeasures d = measure_distortion(half.mesh, r.UV);
    std::printf("| %s | %d | %.3f | %.3f (%d) | %.1f | %d | **%.3f** | %.3f | %.4f | %.4f | %d | %s |\n",
                half.name.c_str(), half.mesh.triangle_count(), r.seconds_init, r.seconds_factorize, r.factorizations,
                r.iterations > 0 ? 1e3 * r.seconds_iterations / r.iterations : 0.0, r.iterations, r.seconds_total,
                t.cpu_s, d.D_angle, d.D_area, r.flipped_triangles, r.notes.empty() ? "" : r.notes.front().c_str());
    std::fflush(stdout);
    ours.push_back(std::move(t));
  }
  if (starts) print_start_comparison(halves);
  if (arap_only) return 0;

  std::printf("\n## Baselines measured in the same run\n\n"
              "Plain = same start map and Laplacian, no Anderson acceleration; refactorizing = plain ARAP that "
              "analyses and factors the Laplacian again every iteration (per-iteration cost measured over 5 "
              "iterations, total = init + that x the plain iteration count).\n\n");
  std::printf("| triangles | ours total s | plain iterations | plain total s | refactorizing s/iteration | "
              "refactorizing factorizations | refactorizing total s | plain/ours | refactorizing/ours |\n"
              "|---|---|---|---|---|---|---|---|---|\n");
  for (size_t i = 0; i < halves.size(); ++i) {
    const BenchHalf& half = halves[i];
    FlattenOptions plain_options;
    plain_options.anderson_acceleration = false;
    const int repeats = half.mesh.triangle_count() > 200000 ? 1 : 2;
    const Timed plain = timed_flatten(half.mesh, plain_options, repeats);
    const double per_iteration = refactorizing_seconds_per_iteration(half.mesh, 5);
    const double refactorizing_total =
        plain.result.seconds_init + plain.result.seconds_factorize / plain.result.factorizations +
        plain.result.iterations * per_iteration;
    const double our_total = ours[i].result.seconds_total;
    std::printf("| %d | %.3f | %d | %.3f | %.3f | %d | %.2f | %.1fx | %.1fx |\n", half.mesh.triangle_count(),
                our_total, plain.result.iterations, plain.result.seconds_total, per_iteration,
                plain.result.iterations + plain.result.factorizations, refactorizing_total,
                plain.result.seconds_total / our_total, refactorizing_total / our_total);
    std::fflush(stdout);
  }

  const double segment_s = segmentation_seconds(100000, 3);
  if (segment_s >= 0) {
    std::printf("\n## Segmentation (engine/segment) of a generated EU 42 last of 100,000 triangles: %.3f s "
                "(wall, best of 3)\n", segment_s);
  }

  std::printf("\n## Sparse Cholesky of the ARAP Laplacian (best of 3, wall s; solve = u and v together)\n\n"
              "| triangles | backend | ordering | analyse s | factorize s | solve ms |\n|---|---|---|---|---|---|\n");
  for (const BenchHalf& half : halves) {
    solver_rows(half);
    std::fflush(stdout);
  }

  print_method_comparison(halves);
  return 0;
}
