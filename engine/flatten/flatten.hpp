#pragma once
// Flattening a disk-shaped half of a last into a 2D mold with minimal stretch.
//
// ARAP (default): L. Liu, L. Zhang, Y. Xu, C. Gotsman, S. J. Gortler, "A Local/Global Approach to Mesh
// Parameterization", SGP 2008, as used in M. Sabaliauskas' thesis (Vilnius University 2017, sections 2.2-2.4):
// analytic 2x2 SVD in the local step, the Laplacian factored once by sparse Cholesky for the global step,
// Anderson acceleration of the iteration (anderson_acceleration.hpp).
// Start map (ArapStart): by default a conformal map that keeps the boundary's lengths, by Boundary First
// Flattening (R. Sawhney, K. Crane, ACM TOG 37(1), 2017; boundary_first_start.hpp), which has the half's
// unrolled global shape, so ARAP only redistributes scale; it costs one numeric factorization of the
// fixed-boundary Laplacian, sharing the symbolic analysis with ARAP's. The older start, one global step
// with every triangle turned onto the half's mean plane (plane_rotation_start.hpp), needs no factorization
// of its own but leaves halves that wrap around the foot rolled up: ARAP then needs hundreds of iterations
// (docs/benchmarks-flatten.md). If ARAP folds triangles (it can, where the surface is far from developable),
// they are untangled locally (untangle.hpp, star_untangle.hpp) and polished with flip-guarded steps; if
// that fails, flip-guarded ARAP restarts from the flip-free Tutte embedding (tutte_embedding.hpp, one more
// factorization). Either way FlattenResult::notes says what happened and flipped_triangles what is left
// (0 in every case we have seen). If the result's outline crosses itself, ARAP is rerun bijectively from a
// start with a simple outline: a boundary barrier repels the outline's parts that come near each other
// (Smith & Schaefer 2015; barrier_arap_iterations.hpp) and the steps are cut so the outline keeps a
// clearance (outline_clearance.hpp).
// LSCM: B. Lévy, S. Petitjean, N. Ray, J. Maillot, SIGGRAPH 2002 (lscm.hpp), for comparison.
// ABF++: A. Sheffer, B. Lévy, M. Mogilnitsky, A. Bogomyakov, ACM TOG 24(2), 2005: the corner angles by
// Newton's method (abf_angles.hpp), then the map by least squares (abf_reconstruction.hpp), scaled to the
// 3D area; folds are untangled locally (untangle.hpp), else it falls back to ARAP (notes say which).
// A Newton that does not reach its tolerance keeps its best angles, converged = false and a note.
//
// Usage:
//   lastcut::FlattenResult r = lastcut::flatten(half);          // half: TriMesh in mm, a disk
//   lastcut::DistortionMeasures d = lastcut::measure_distortion(half, r.UV);
#include <Eigen/Core>
#include <string>
#include <vector>

#include "engine/core/tri_mesh.hpp"
#include "engine/flatten/distortion.hpp"
#include "engine/flatten/sparse_cholesky.hpp"
#include "engine/flatten/svd2x2.hpp"

namespace lastcut {

enum class FlattenMethod { Arap, Lscm, Abf };

// Where ARAP starts (see above). Auto: the plane-rotation start when less than 1 % of the half's area
// faces away from its mean normal (it then lays the half out unrolled, and costs no factorization),
// the boundary-first start otherwise (measured: generated last halves 0.2-0.7 %, FIND foot halves
// 3.8-20 %; docs/benchmarks-flatten.md).
enum class ArapStart { Auto, BoundaryFirst, PlaneRotation };

struct FlattenOptions {
  FlattenMethod method = FlattenMethod::Arap;
  int max_iterations = 200;                  // ARAP local/global iterations at most
  double relative_energy_tolerance = 1e-6;   // stop when (E_prev - E) <= tol * E_prev
  SparseSolver solver = SparseSolver::Auto;
  // Start from the flip-free Tutte map (one more factorization) and halve ARAP steps that would fold a
  // triangle (slower, more distortion); by default ARAP runs free and the few folds it may leave are
  // repaired afterwards (see FlattenResult::notes).
  bool flip_guard = false;
  ArapStart start = ArapStart::Auto;  // ignored with flip_guard (which starts from the Tutte map)
  // Anderson acceleration of the local/global iteration (Peng et al. 2018): same fixed point, fewer iterations.
  bool anderson_acceleration = true;
  // ARAP whose outline crosses itself is rerun with the outline filter (outline_clearance.hpp) from a start
  // map with a simple outline: the mold then has a cuttable outline, non-adjacent boundary edges at least
  // outline_clearance_mm apart. 0.1 mm: five times the mold's outline simplification tolerance (0.02 mm),
  // so a narrow notch stays a slit the simplified outline does not close, yet well below a knife's accuracy.
  bool injective_outline = true;
  double outline_clearance_mm = 0.1;
  // The rerun is bijective ARAP (barrier_arap_iterations.hpp): outline vertices and edges closer than this
  // repel each other (Smith & Schaefer 2015), so the outline's parts that ARAP would lay over each other
  // end up side by side, at most this far apart, instead of the iteration stopping where they meet.
  double barrier_reach_mm = 1.0;
  // Iterations of that rerun at most: from the Tutte map (when no iterate of plain ARAP was bijective) a
  // half needs hundreds (the 420-degree ramp of the tests: ~450), from a replayed iterate a dozen.
  int bijective_max_iterations = 1000;
  // ABF++ (method Abf): Newton iterations at most and the tolerance on ||grad L|| (abf_angles.hpp).
  int abf_max_newton_iterations = 50;
  double abf_gradient_tolerance = 1e-6;
};

struct FlattenResult {
  Eigen::MatrixXd UV;              // #V x 2, mm, same vertex order as the input, centred on the vertex mean
  int iterations = 0;              // ARAP global steps (ABF++: Newton steps)
  int factorizations = 0;          // numeric sparse Cholesky factorizations: 1, +1 if the Tutte map was needed
  double seconds_init = 0;         // checks, frames, pattern, start map (and the Tutte map if it was needed)
  double seconds_factorize = 0;    // symbolic analysis + numeric factorization of the ARAP Laplacian
  double seconds_iterations = 0;   // ARAP local/global iterations (ABF++: Newton, reconstruction and repair)
  double seconds_total = 0;
  int flipped_triangles = 0;       // after the repair/fallback below
  bool converged = false;          // ARAP reached the energy tolerance (LSCM: always true; ABF++: its Newton did)
  double energy_start = 0, energy_final = 0;  // ARAP energy (mm^2) of the start map and the result
  std::vector<std::string> notes;  // e.g. "3 steps shortened to avoid flipped triangles", "fell back to ..."
};

// disk: a connected, manifold, oriented triangle mesh with one boundary loop, in mm.
// Throws EngineError (one line) if it is not a disk or has zero-area triangles.
FlattenResult flatten(const TriMesh& disk, const FlattenOptions& options = {});
// The same with the disk's topology already built (build_mesh_topology(disk.F, disk.V.rows()));
// it is checked here.
FlattenResult flatten(const TriMesh& disk, const MeshTopology& topology, const FlattenOptions& options = {});

}  // namespace lastcut
