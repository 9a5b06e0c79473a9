#pragma once
// Coarse-space correction for ARAP's global step: maps that differ from the current one by a trilinear
// function on a 3D lattice of cubes laid over the surface.
//
// Two-level subspace correction: J. Xu, "Iterative methods by space decomposition and subspace
// correction", SIAM Review 34(4), 1992. A lattice of cells around the surface rather than a coarse mesh, as
// in M. Botsch, M. Pauly, M. Wicke, M. Gross, "Adaptive space deformations based on rigid cells",
// Computer Graphics Forum 26(3), Eurographics 2007: it needs no simplification of the mesh and costs
// O(#V) to build.
//
// Why: ARAP's local/global iteration removes high-frequency errors in a few steps, but the smooth,
// global ones (the half unrolling, scale spreading over the whole outline) shrink by only a few percent
// per step on the foot halves (hundreds of steps to converge, docs/benchmarks-flatten.md). Restricted to
// u + P c with P the lattice's trilinear interpolation at the vertices (#V-1 x #nodes, ~2-4k nodes), the
// global step is the small system (P^T L P) c = P^T (b - L u): the same energy minimised over a subspace
// that holds exactly those smooth errors, at the cost of a local step and two sparse products.
// Where two sheets of the surface pass through one cube (e.g. between toes) they share its nodes: the
// subspace is smaller there, nothing is wrong (the fine steps that follow are not restricted).
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "engine/core/tri_mesh.hpp"
#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/sparse_cholesky.hpp"

namespace lastcut {

class LatticeSubspace {
 public:
  // mesh: the half (mm); laplacian: ARAP's pinned Laplacian (its rows are the subspace's rows, the pinned
  // vertex stays where it is). cell_mm: the cubes' edge. Factors P^T L P once (a few thousand unknowns).
  LatticeSubspace(const TriMesh& mesh, const ReducedLaplacian& laplacian, double cell_mm);

  // X = P (P^T L P)^-1 P^T R: the best correction in the subspace for the residual R of the reduced
  // system (rows of laplacian.matrix x 2 columns, u and v); mm.
  Eigen::MatrixXd correction(const Eigen::MatrixXd& residual) const;

  int node_count() const { return static_cast<int>(prolongation_.cols()); }

 private:
  Eigen::SparseMatrix<double, Eigen::RowMajor> prolongation_;  // P: rows of the reduced system x nodes
  Eigen::SparseMatrix<double, Eigen::RowMajor> restriction_;   // P^T
  SparseCholesky coarse_;                                      // factor of P^T L P (+ a tiny diagonal)
};

// Cube edge (mm) for a lattice of about `cells` cubes over a surface of area_mm2: sqrt(area / cells).
double lattice_cell_mm(double area_mm2, int cells);

}  // namespace lastcut
