#pragma once
// ARAP with chosen edges held at their 3D length: a piece's sewn edges (issue 34, "seams match").
//
// Two pieces sewn along a line are flattened each on its own, and plain ARAP lets each one stretch or
// shrink its outline by up to 1.6 % where that spreads its distortion best (the derby's vamp line: 2.6 mm
// longer on the vamp than on the quarters). The closing room stitches them mark to mark, so both sides of
// a seam must keep the seam's length on the last. This adds a spring per held edge (i, j) to the ARAP
// energy of Liu et al. 2008 (arap_iterations.hpp):
//   E(u, R, d) = sum_t sum_(i,j) w_ij^t || (u_j - u_i) - R_t (x_j - x_i) ||^2
//              + sum_held s_ij || (u_j - u_i) - d_ij ||^2,   |d_ij| = |x_j - x_i| (3D length)
// and keeps the local/global scheme: the local step takes R_t as before and d_ij as the 3D length along
// the edge's current direction (the closest vector of that length); the global step solves
// (L + L_held) u = b (L_held: the springs' weights) once per iteration with a matrix factored once. Each step minimises E over its
// own variables, so E never rises. This is the edge-length term of the "as-rigid-as-possible with
// constraints" family (e.g. the boundary springs of Bouaziz et al., "Projective Dynamics", SIGGRAPH 2014,
// whose local/global edge-length projection this is); the weights make the held lengths nearly exact
// while the rest of the piece relaxes around them.
//
// The steps are flip-guarded as in arap_iterations.hpp (against flips only): no triangle of the start
// map flips, so a flip-free flattening stays flip-free.
//
// Usage: start from a flattening (flatten.hpp), hold the edges, then measure the distortion again.
#include <Eigen/Core>

#include <array>
#include <vector>

#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"
#include "engine/flatten/sparse_cholesky.hpp"

namespace lastcut {

struct HeldLengthOptions {
  // Spring weight against the cotangent weights (dimensionless, like them): each edge's s is this times
  // the mean diagonal of the cotangent Laplacian at its two ends (at least 1), so an edge beside a
  // sliver, whose cotangent weights are thousands, is held as firmly as any. With 1000 the first global
  // step does nearly all: after 5 iterations the derby's seams match within 0.05 mm (docs/pieces.md).
  double weight = 1000;
  int max_iterations = 5;
  double relative_energy_tolerance = 1e-6;  // stop when (E_prev - E) <= tol * E_prev
  SparseSolver solver = SparseSolver::Auto;
};

struct HeldLengthReport {
  int iterations = 0;
  bool converged = false;
  int shortened_steps = 0;        // steps halved so no triangle would flip or collapse
  bool stalled_on_flips = false;  // stopped: a 1/1024 step would still flip or collapse one
  double energy_start = 0, energy_final = 0;  // E above (mm^2)
};

// mesh: #V x 3 mm, a disk (topology of it); UV: #V x 2 mm, the start map on entry (a flattening of mesh),
// the result on exit (the last step that made no triangle worse); held: mesh edges as vertex pairs (either order). No held edges: UV is left as it is.
// Throws EngineError when the system cannot be factored (degenerate triangles).
HeldLengthReport hold_edge_lengths(const TriMesh& mesh, const MeshTopology& topology, const std::vector<std::array<int, 2>>& held,
                                   Eigen::MatrixXd& UV, const HeldLengthOptions& options = {});

}  // namespace lastcut
