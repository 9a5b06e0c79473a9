#pragma once
// ABF++ step 1: the corner angles of a flattening, by Newton's method on the Lagrangian of the
// angle-based flattening problem.
//
// A. Sheffer, B. Lévy, M. Mogilnitsky, A. Bogomyakov, "ABF++: Fast and Robust Angle Based Flattening",
// ACM Transactions on Graphics 24(2), 2005, sections 3-4, building on A. Sheffer, E. de Sturler,
// "Parameterization of faceted surfaces for meshing using angle-based flattening", Engineering with
// Computers 17, 2001.
//   Variables  alpha: the 3 angles of every triangle (3 #F, rad).
//   Energy     E = sum_c (alpha_c - beta_c)^2 / beta_c^2, beta the 3D angles, scaled at every interior
//              vertex so that they sum to 2 pi there (boundary angles are kept).
//   Constraints, with lambda a multiplier each:
//     triangle   alpha_0 + alpha_1 + alpha_2 - pi = 0                          (#F)
//     planarity  sum of the angles around an interior vertex - 2 pi = 0         (#interior)
//     wheel      sum log sin(alpha_next) - sum log sin(alpha_prev) = 0 around an interior vertex v
//                (#interior): next/prev are the corners after/before v in each triangle of its star.
//                The law of sines gives the ratio of the two edges at v in each triangle; their product
//                around v must be 1 for the edges to close. The papers write the product form; the log
//                form has the same zeros, a Jacobian entry of +-cot(alpha), and a diagonal Hessian.
//   Positivity alpha > 0 (and < pi): not a Newton constraint; kept by shortening a Newton step that would
//              leave (0, pi) to half the remaining distance (never needed on our meshes so far: the
//              1 / beta^2 weights hold small angles near their targets).
// Newton step (the ABF++ block elimination): the KKT system [Lambda J^T; J 0] with Lambda diagonal
// (2 / beta^2 from E plus the wheel multipliers' -lambda / sin^2, clamped below at 1 / beta^2 so that
// the reduced system stays positive definite),
// J = [J_tri; J_vertex]. Lambda is inverted per corner, then J_tri Lambda^-1 J_tri^T (diagonal, per
// triangle), leaving a symmetric positive definite system in the vertex multipliers only
// (2 #interior unknowns, the mesh's vertex adjacency in 2x2 blocks), factored by sparse Cholesky; the
// corner angles and triangle multipliers follow by back substitution.
// Stop when ||grad L|| (the gradient of the Lagrangian in alpha and in all multipliers, i.e. the energy
// stationarity together with every constraint residual) is <= gradient_tolerance (1e-6 as in the paper;
// radians for the sums, unitless for the wheel).
#include <vector>

#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"
#include "engine/flatten/sparse_cholesky.hpp"

namespace lastcut {

struct AbfOptions {
  int max_newton_iterations = 50;
  double gradient_tolerance = 1e-6;  // on ||grad L||_2, see above
  SparseSolver solver = SparseSolver::Auto;
};

struct AbfAngles {
  std::vector<double> alpha;     // 3 #F, rad: corner k of triangle f at 3 f + k; the best iterate
  std::vector<double> beta;      // 3 #F, rad: the optimal (target) angles
  int iterations = 0;            // Newton steps taken (one sparse factorization each)
  int shortened_steps = 0;       // steps shortened to keep every angle in (0, pi)
  bool converged = false;        // ||grad L|| <= gradient_tolerance
  double gradient_norm = 0;      // ||grad L||_2 at alpha
};

// Worst residuals of the ABF constraints at alpha (each an absolute value).
struct AbfResiduals {
  double triangle_rad = 0;  // max |alpha_0 + alpha_1 + alpha_2 - pi|
  double vertex_rad = 0;    // max |sum at an interior vertex - 2 pi|
  double wheel = 0;         // max |sum log sin(next) - sum log sin(prev)|, unitless
};

// Interior-vertex flags (#V): 1 unless the vertex is on a boundary loop of topology.
std::vector<char> interior_vertices(const MeshTopology& topology);

// The 3D corner angles of mesh (3 #F, rad), scaled at interior vertices to sum to 2 pi.
std::vector<double> abf_optimal_angles(const TriMesh& mesh, const MeshTopology& topology);

// Newton from alpha_start (3 #F, rad, in (0, pi); usually beta) towards the ABF minimum for the target
// angles beta (3 #F, rad, > 0). F: #F x 3; topology: of F, a checked disk. Never throws on
// non-convergence: the result says converged = false and holds the iterate with the smallest ||grad L||.
AbfAngles solve_abf_angles(const Eigen::MatrixXi& F, const MeshTopology& topology, const std::vector<double>& beta,
                           const std::vector<double>& alpha_start, const AbfOptions& options = {});

// The same from alpha = beta = abf_optimal_angles(mesh, topology).
AbfAngles solve_abf_angles(const TriMesh& mesh, const MeshTopology& topology, const AbfOptions& options = {});

AbfResiduals abf_residuals(const Eigen::MatrixXi& F, const MeshTopology& topology, const std::vector<double>& alpha);

}  // namespace lastcut
