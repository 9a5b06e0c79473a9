// The flattening pipeline: checks, start map, ARAP, LSCM or ABF++, flip check and fallback; see flatten.hpp.
#include "engine/flatten/flatten.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>

#include "engine/core/engine_error.hpp"
#include "engine/flatten/abf_angles.hpp"
#include "engine/flatten/abf_reconstruction.hpp"
#include "engine/flatten/arap_iterations.hpp"
#include "engine/flatten/barrier_arap_iterations.hpp"
#include "engine/flatten/boundary_barrier.hpp"
#include "engine/flatten/boundary_first_start.hpp"
#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/lscm.hpp"
#include "engine/flatten/outline_clearance.hpp"
#include "engine/flatten/plane_rotation_start.hpp"
#include "engine/flatten/tutte_embedding.hpp"
#include "engine/flatten/untangle.hpp"

namespace lastcut {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The flip-free Tutte start map (tutte_embedding.hpp), on its own copy of the pattern and its own factor:
// the ARAP factor stays intact. Costs one more factorization.
Eigen::MatrixXd flip_free_start(const TriMesh& disk, const TriangleFrames& frames, const MeshTopology& topology,
                                const ReducedLaplacian& arap_laplacian, const FlattenOptions& options,
                                FlattenResult& result) {
  ReducedLaplacian laplacian = arap_laplacian;
  SparseCholesky factor(options.solver);
  factor.analyze_pattern(laplacian.matrix);
  ++result.factorizations;
  return tutte_embedding(disk, frames, topology, laplacian, factor);
}

// If UV's outline crosses itself, replaces UV by injective ARAP (outline filter, outline_clearance.hpp) from
// start_map when that is flip-free with a simple outline, else from the Tutte map (a convex outline).
void make_outline_simple(const TriMesh& disk, const TriangleFrames& frames, const MeshTopology& topology,
                         const ReducedLaplacian& laplacian, const SparseCholesky& factor,
                         const OutlineClearance& outline, const Eigen::MatrixXd& start_map,
                         const FlattenOptions& options, Eigen::MatrixXd& UV, FlattenResult& result) {
  if (!outline.crosses(UV)) return;
  Eigen::MatrixXd injective = start_map;
  const bool from_start = count_flipped_triangles(disk.F, injective) == 0 && !outline.crosses(injective);
  // The unguarded iterations from the start map, replayed (they are deterministic) up to the last iterate
  // before the first that folds or crosses: injective, and much nearer the minimum than the start map.
  int replayed = 0;
  if (from_start) {
    replayed = run_arap_iterations(frames, laplacian, factor, injective, options.max_iterations,
                                   options.relative_energy_tolerance, false, options.anderson_acceleration, &outline)
                   .iterations;
  } else {
    injective = flip_free_start(disk, frames, topology, laplacian, options, result);
  }
  const std::vector<int>& loop = outline.loop();
  std::vector<double> arc_mm(loop.size());
  for (size_t k = 0; k < loop.size(); ++k)
    arc_mm[k] = (disk.V.row(loop[(k + 1) % loop.size()]) - disk.V.row(loop[k])).norm();
  BoundaryBarrierOptions barrier_options;
  barrier_options.activation_mm = options.barrier_reach_mm;
  barrier_options.least_activation_mm = std::min(options.barrier_reach_mm, 2.0 * options.outline_clearance_mm);
  const BoundaryBarrier barrier(loop, arc_mm, barrier_options);
  const BarrierArapReport report =
      run_barrier_arap_iterations(frames, laplacian, factor, barrier, outline, injective, options.bijective_max_iterations,
                                  options.relative_energy_tolerance, options.anderson_acceleration);
  UV = std::move(injective);
  result.iterations += replayed + report.iterations;
  result.energy_final = report.energy_final;
  result.converged = report.converged;
  const std::string from =
      from_start ? "last of " + std::to_string(replayed) + " replayed ARAP iterations before a crossing or fold"
                 : std::string("Tutte map");
  char line[400];
  std::snprintf(line, sizeof line,
                "the ARAP outline crossed itself: reran bijective ARAP (boundary barrier within %.2f mm) from the "
                "%s: %d iterations (%d conjugate gradients), %d steps shortened, %d outline vertex-edge pairs held "
                "apart, outline clearance %.2f mm%s",
                options.barrier_reach_mm, from.c_str(), report.iterations, report.conjugate_gradients, report.shortened_steps,
                report.active_pairs_final, options.outline_clearance_mm,
                report.stalled ? "; stopped where even a 2^-20 step would fold, cross or not lower the energy" : "");
  result.notes.push_back(line);
}

void run_arap(const TriMesh& disk, const TriangleFrames& frames, const MeshTopology& topology,
              const FlattenOptions& options, FlattenResult& result) {
  auto clock = Clock::now();
  ReducedLaplacian laplacian = pinned_cotangent_laplacian(frames, topology);
  SparseCholesky factor(options.solver);
  result.seconds_init += seconds_since(clock);

  // One symbolic analysis serves the start map's fixed-boundary system and ARAP's Laplacian (same pattern).
  clock = Clock::now();
  factor.analyze_pattern(laplacian.matrix);
  result.seconds_factorize += seconds_since(clock);

  // Share of the area facing away from the mean normal above which the plane start lays a half rolled up.
  constexpr double kMaxFacingAwayForPlaneStart = 0.01;
  ArapStart start_kind = options.start;
  if (start_kind == ArapStart::Auto)
    start_kind = area_facing_away_share(disk) > kMaxFacingAwayForPlaneStart ? ArapStart::BoundaryFirst
                                                                             : ArapStart::PlaneRotation;
  std::optional<Eigen::MatrixXd> start;
  if (!options.flip_guard && start_kind == ArapStart::BoundaryFirst) {
    clock = Clock::now();
    start = boundary_first_start(disk, frames, topology, laplacian, factor);
    ++result.factorizations;
    if (!start->allFinite()) start.reset();
    // Back to ARAP's own system: the cotangent Laplacian with only the pinned vertex fixed.
    std::vector<char> fixed(disk.V.rows(), 0);
    fixed[static_cast<size_t>(laplacian.pinned)] = 1;
    assemble_laplacian(frames, frames.half_weight, fixed, laplacian);
    result.seconds_init += seconds_since(clock);
  }

  clock = Clock::now();
  factor.factorize(laplacian.matrix);
  ++result.factorizations;
  result.seconds_factorize += seconds_since(clock);

  clock = Clock::now();
  // Flip-guarded ARAP keeps a flip-free start flip-free, so it starts from the Tutte map.
  if (!options.flip_guard && start_kind == ArapStart::PlaneRotation)
    start = plane_rotation_start(disk, frames, topology, laplacian, factor);
  if (options.flip_guard) {
    start = flip_free_start(disk, frames, topology, laplacian, options, result);
  } else if (!start) {
    result.notes.push_back(start_kind == ArapStart::BoundaryFirst
                               ? "the boundary-first start map failed: started from the Tutte embedding"
                               : "the half faces no one way (mean normal near zero): started from the Tutte embedding");
    start = flip_free_start(disk, frames, topology, laplacian, options, result);
  }
  Eigen::MatrixXd UV = std::move(*start);
  result.seconds_init += seconds_since(clock);
  const Eigen::MatrixXd start_map = UV;  // where an injective rerun starts if the result's outline crosses

  clock = Clock::now();
  // Iterations in a row with a crossed outline after which the unguarded run gives up (the injective
  // rerun replaces its result anyway). No half measured crosses for a while and comes clear again.
  constexpr int kGiveUpAfterCrossing = 8;
  const OutlineClearance outline(topology.boundary_loops[0], options.outline_clearance_mm);
  const bool watch_outline = options.injective_outline && !options.flip_guard;
  const ArapIterationReport report = run_arap_iterations(
      frames, laplacian, factor, UV, options.max_iterations, options.relative_energy_tolerance, options.flip_guard,
      options.anderson_acceleration, watch_outline ? &outline : nullptr, watch_outline ? kGiveUpAfterCrossing : 0);
  result.iterations = report.iterations;
  result.converged = report.converged;
  result.energy_start = report.energy_start;
  result.energy_final = report.energy_final;
  if (report.shortened_steps > 0) {
    result.notes.push_back(std::to_string(report.shortened_steps) + " ARAP steps shortened so that no triangle flips");
  }
  if (report.gave_up_crossed) {
    result.notes.push_back("the ARAP outline crossed itself " + std::to_string(kGiveUpAfterCrossing) +
                           " iterations in a row: stopped after " + std::to_string(report.iterations));
  } else if (!report.converged && !report.stalled_on_flips) {
    result.notes.push_back("ARAP reached the iteration limit (" + std::to_string(options.max_iterations) +
                           ") before the energy tolerance");
  }

  // Repair: ARAP may fold a few triangles where the surface is far from developable. Untangle them
  // locally, then let flip-guarded ARAP steps relax the neighbourhood without folding anything again.
  // A run that gave up on its crossed outline goes straight to the injective rerun.
  const int flips = report.gave_up_crossed ? 0 : count_flipped_triangles(disk.F, UV);
  if (flips > 0) {
    const UntangleReport untangled = untangle_flips(frames, topology, UV);
    if (untangled.flipped_after == 0) {
      constexpr int kPolishIterations = 30;
      const ArapIterationReport polish = run_arap_iterations(frames, laplacian, factor, UV, kPolishIterations,
                                                             options.relative_energy_tolerance, true);
      result.iterations += polish.iterations;
      result.energy_final = polish.energy_final;
      result.notes.push_back(std::to_string(flips) + " flipped triangles repaired: " +
                             std::to_string(untangled.moved_vertices) + " vertices relaxed within " +
                             std::to_string(untangled.rings) + " rings, then " + std::to_string(polish.iterations) +
                             " flip-guarded ARAP iterations");
    } else {
      // Fall back to the flip-free Tutte map and flip-guarded ARAP from there.
      UV = flip_free_start(disk, frames, topology, laplacian, options, result);
      const ArapIterationReport guarded = run_arap_iterations(frames, laplacian, factor, UV, options.max_iterations,
                                                              options.relative_energy_tolerance, true);
      result.iterations += guarded.iterations;
      result.energy_final = guarded.energy_final;
      result.converged = guarded.converged;
      result.notes.push_back(std::to_string(flips) + " flipped triangles could not be repaired locally; fell back to "
                             "the flip-free Tutte map with flip-guarded ARAP (" +
                             std::to_string(guarded.iterations) + " iterations, more distortion)");
    }
  }
  if (options.injective_outline)
    make_outline_simple(disk, frames, topology, laplacian, factor, outline, start_map, options, UV, result);
  result.seconds_iterations += seconds_since(clock);
  result.UV = std::move(UV);
}

// Replaces result's map by ARAP's, adding ARAP's counts, times and notes (LSCM and ABF++ fallback).
void fall_back_to_arap(const TriMesh& disk, const TriangleFrames& frames, const MeshTopology& topology,
                       const FlattenOptions& options, FlattenResult& result) {
  FlattenResult arap;
  run_arap(disk, frames, topology, options, arap);
  result.UV = std::move(arap.UV);
  result.iterations = arap.iterations;
  result.factorizations += arap.factorizations;
  result.seconds_init += arap.seconds_init;
  result.seconds_factorize += arap.seconds_factorize;
  result.seconds_iterations += arap.seconds_iterations;
  result.converged = arap.converged;
  result.notes.insert(result.notes.end(), arap.notes.begin(), arap.notes.end());
}

// ABF++: angles by Newton (one factorization per step), the map by least squares (one more), then folds
// untangled locally or, failing that, ARAP instead. seconds_iterations holds all of it.
void run_abf(const TriMesh& disk, const TriangleFrames& frames, const MeshTopology& topology,
             const FlattenOptions& options, FlattenResult& result) {
  const auto clock = Clock::now();
  AbfOptions abf_options;
  abf_options.max_newton_iterations = options.abf_max_newton_iterations;
  abf_options.gradient_tolerance = options.abf_gradient_tolerance;
  abf_options.solver = options.solver;
  const AbfAngles angles = solve_abf_angles(disk, topology, abf_options);
  result.iterations = angles.iterations;
  result.factorizations = angles.iterations + 1;
  result.converged = angles.converged;
  if (!angles.converged) {
    char line[200];
    std::snprintf(line, sizeof line,
                  "ABF++ Newton stopped after %d iterations at |grad L| = %.3g (tolerance %.3g): the map is built "
                  "from its best angles",
                  angles.iterations, angles.gradient_norm, options.abf_gradient_tolerance);
    result.notes.push_back(line);
  }
  if (angles.shortened_steps > 0) {
    result.notes.push_back(std::to_string(angles.shortened_steps) +
                           " ABF++ Newton steps shortened to keep every angle between 0 and 180 degrees");
  }
  result.UV = reconstruct_from_angles(disk, topology, angles.alpha, options.solver);
  result.seconds_iterations = seconds_since(clock);

  const int flips = count_flipped_triangles(disk.F, result.UV);
  if (flips == 0) return;
  const UntangleReport untangled = untangle_flips(frames, topology, result.UV);
  if (untangled.flipped_after == 0) {
    result.notes.push_back(std::to_string(flips) + " flipped triangles of the ABF++ map untangled: " +
                           std::to_string(untangled.moved_vertices) + " vertices relaxed within " +
                           std::to_string(untangled.rings) + " rings");
    result.seconds_iterations = seconds_since(clock);
  } else {
    result.notes.push_back("the ABF++ map flipped " + std::to_string(flips) +
                           " triangles that could not be untangled locally; fell back to ARAP");
    result.seconds_iterations = seconds_since(clock);
    fall_back_to_arap(disk, frames, topology, options, result);
  }
}

void check_options(const FlattenOptions& options) {
  if (options.max_iterations < 0 || options.bijective_max_iterations < 0)
    throw EngineError("flatten: max_iterations must not be negative");
  if (!(options.relative_energy_tolerance >= 0.0)) throw EngineError("flatten: energy tolerance must be >= 0");
  if (!(options.outline_clearance_mm >= 0.0)) throw EngineError("flatten: the outline clearance must be >= 0 mm");
  if (!(options.barrier_reach_mm > options.outline_clearance_mm))
    throw EngineError("flatten: the boundary barrier's reach must exceed the outline clearance");
  if (options.abf_max_newton_iterations < 0) throw EngineError("flatten: ABF++ Newton iterations must not be negative");
  if (!(options.abf_gradient_tolerance >= 0.0)) throw EngineError("flatten: ABF++ tolerance must be >= 0");
}

// disk: checked by check_disk; start: when the caller began (seconds_init includes the check).
FlattenResult flatten_checked_disk(const TriMesh& disk, const MeshTopology& topology, const FlattenOptions& options,
                                   Clock::time_point start) {
  FlattenResult result;
  const TriangleFrames frames = compute_triangle_frames(disk);
  result.seconds_init = seconds_since(start);

  if (options.method == FlattenMethod::Lscm) {
    const auto clock = Clock::now();
    LscmResult conformal = lscm(disk, frames, topology, options.solver);
    result.factorizations = 1;
    result.seconds_factorize = conformal.seconds_factorize;
    result.seconds_init += seconds_since(clock) - conformal.seconds_factorize;
    result.converged = true;
    const int flips = count_flipped_triangles(disk.F, conformal.UV);
    if (flips == 0) {
      result.UV = std::move(conformal.UV);
    } else {
      result.notes.push_back("LSCM flipped " + std::to_string(flips) +
                             " triangles; fell back to ARAP");
      fall_back_to_arap(disk, frames, topology, options, result);
    }
  } else if (options.method == FlattenMethod::Abf) {
    run_abf(disk, frames, topology, options, result);
  } else {
    run_arap(disk, frames, topology, options, result);
  }

  result.UV = (result.UV.rowwise() - result.UV.colwise().mean()).eval();
  result.flipped_triangles = count_flipped_triangles(disk.F, result.UV);
  if (result.flipped_triangles > 0) {
    result.notes.push_back(std::to_string(result.flipped_triangles) + " triangles remain flipped in the mold");
  }
  result.seconds_total = seconds_since(start);
  return result;
}

}  // namespace

FlattenResult flatten(const TriMesh& disk, const FlattenOptions& options) {
  check_options(options);
  const auto start = Clock::now();
  const MeshTopology topology = check_disk(disk);
  return flatten_checked_disk(disk, topology, options, start);
}

FlattenResult flatten(const TriMesh& disk, const MeshTopology& topology, const FlattenOptions& options) {
  check_options(options);
  const auto start = Clock::now();
  check_disk(disk, topology);
  return flatten_checked_disk(disk, topology, options, start);
}

}  // namespace lastcut
