#pragma once
// Local/global iterations of As-Rigid-As-Possible parameterization with a free boundary.
//
// L. Liu, L. Zhang, Y. Xu, C. Gotsman, S. J. Gortler, "A Local/Global Approach to Mesh Parameterization",
// Eurographics Symposium on Geometry Processing (SGP) 2008. Energy, per triangle t and edge (i, j) of t:
//   E(u, R) = sum_t sum_(i,j) w_ij^t || (u_j - u_i) - R_t (x_j - x_i) ||^2
// with w the cotangent weights and x the triangle's own isometric 2D frame. Local step: R_t is the
// closest rotation to the cross-covariance S_t (closest_rotation2x2). Global step: the Laplacian system
// L u = b, factored once per mesh; each iteration is one back-substitution for u and v together.
// The energy is translation invariant, so pinning one vertex at its current position gives exactly the
// unconstrained minimiser: the result does not depend on where the mesh sits or how it is turned in 3D.
// Unguarded iterations are Anderson-accelerated (anderson_acceleration.hpp) with an energy safeguard.
#include <Eigen/Core>

#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/outline_clearance.hpp"
#include "engine/flatten/sparse_cholesky.hpp"

namespace lastcut {

struct ArapIterationReport {
  int iterations = 0;          // global steps taken
  double energy_start = 0;     // ARAP energy of the start map (mm^2)
  double energy_final = 0;     // ARAP energy of the result (mm^2)
  bool converged = false;      // relative energy change fell below the tolerance
  int shortened_steps = 0;     // global steps shortened so no triangle would flip or collapse
  int rejected_accelerations = 0;  // Anderson steps that did not lower the energy (plain step taken)
  bool stalled_on_flips = false;  // stopped: a 1/1024 step would flip or collapse a triangle
  bool gave_up_crossed = false;   // stopped: the outline crossed itself give_up_after_crossing iterations in a row
};

// UV (#V x 2, mm) is the start map on entry and the result on exit. `laplacian` holds the cotangent
// Laplacian pinned at laplacian.pinned and `factor` its factorization. With flip_guard, a global step that
// would flip or collapse (UV area < 5% of 3D area) any triangle that was not so before is halved until it does not
// (the energy still decreases: it is convex in u for fixed rotations), so a flip-free start stays flip-free.
// Guarded runs take no `outline` (EngineError): keeping an outline clear is bijective ARAP's job
// (barrier_arap_iterations.hpp). Without flip_guard, an `outline` makes the run stop at the first
// iterate that flips a triangle or whose outline crosses, UV then holding the iterate before it (the bijective rerun's start, flatten.cpp).
// Unless give_up_after_crossing > 0: then the run goes on through folds and crossings, as without
// `outline`, but gives up (gave_up_crossed) once the outline has crossed itself at that many iterations
// in a row, UV holding the last iterate: a result whose outline crosses is replaced by the bijective
// rerun anyway, so the iterations after that are wasted (FIND medial half: crossed from the 2nd of 54).
// Without `outline` the iterations are exactly those of before; with it, the iterates are the same.
ArapIterationReport run_arap_iterations(const TriangleFrames& frames, const ReducedLaplacian& laplacian,
                                        const SparseCholesky& factor, Eigen::MatrixXd& UV, int max_iterations,
                                        double relative_energy_tolerance, bool flip_guard, bool accelerate = true,
                                        const OutlineClearance* outline = nullptr, int give_up_after_crossing = 0);

}  // namespace lastcut
