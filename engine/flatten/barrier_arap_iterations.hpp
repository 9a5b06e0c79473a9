#pragma once
// Bijective ARAP: local/global iterations on ARAP's energy plus two barriers, from a map that is already
// bijective (flip-free, simple outline), keeping it so and converging where plain ARAP would fold or lay
// the outline over itself.
//
// Energy: E(UV) = E_ARAP(UV) (Liu et al. 2008, arap_iterations.hpp)
//               + E_B(UV): outline vertices repel outline edges they come near (J. Smith, S. Schaefer,
//                 "Bijective Parameterization with Free Boundaries", SIGGRAPH 2015; boundary_barrier.hpp)
//               + E_F(UV): triangles resist shrinking towards zero area (C. Schüller et al., "Locally
//                 Injective Mappings", SGP 2013; fold_barrier.hpp).
// Each step solves (L + H / 2) delta = b(R) - L UV - grad(E_B + E_F) / 2: ARAP's global step with the
// barriers' gradient and an upper bound H of their Gauss-Newton curvature, a quadratic proxy of the whole
// energy (S. Z. Kovalsky, M. Galun, Y. Lipman, "Accelerated Quadratic Proxy for Geometric Optimization",
// ACM TOG 35(4), 2016). H has one rank per active pair or thin triangle, so the system is solved by
// conjugate gradients preconditioned with ARAP's own factorization (no new factorization); without active
// terms the step is ARAP's global step.
// The step is halved until no triangle gets worse (the flip guard of arap_local_step.hpp), the outline
// keeps its clearance (outline_clearance.hpp) and the energy decreases. Without the fold barrier, the
// triangles at the flip guard cut every step of the whole map to nothing (jamming: the FIND medial half
// stalled at an ARAP energy of 316 mm^2; with it the iteration converges at 289 mm^2).
// Anderson acceleration (anderson_acceleration.hpp) mixes the steps; a mixed point is kept only when it
// passes the same tests.
#include <Eigen/Core>

#include "engine/flatten/boundary_barrier.hpp"
#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/outline_clearance.hpp"
#include "engine/flatten/sparse_cholesky.hpp"

namespace lastcut {

struct BarrierArapReport {
  int iterations = 0;          // global steps taken
  double energy_start = 0;     // ARAP energy (mm^2) of the start map
  double energy_final = 0;     // ARAP energy (mm^2) of the result, barrier not included
  double barrier_final = 0;    // E_B of the result (mm^2)
  int active_pairs_final = 0;  // outline vertex-edge pairs closer than the barrier's reach in the result
  bool converged = false;      // the relative change of E_ARAP + E_B fell below the tolerance
  int shortened_steps = 0;     // steps cut short by the guard or the energy test
  int conjugate_gradients = 0; // iterations of the steps' linear solves (conjugate gradients), all steps
  bool stalled = false;        // stopped: not even a 2^-20 step passed the tests (the map stays bijective)
};

// UV (#V x 2, mm): a bijective start map on entry (every triangle positive, outline simple: not checked
// here, the guards only keep what the start has), the result on exit. `laplacian`, `factor`: ARAP's pinned
// cotangent Laplacian and its factorization, as for run_arap_iterations.
BarrierArapReport run_barrier_arap_iterations(const TriangleFrames& frames, const ReducedLaplacian& laplacian,
                                              const SparseCholesky& factor, const BoundaryBarrier& barrier,
                                              const OutlineClearance& outline, Eigen::MatrixXd& UV,
                                              int max_iterations, double relative_energy_tolerance,
                                              bool accelerate = true);

}  // namespace lastcut
