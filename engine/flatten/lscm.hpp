#pragma once
// Least Squares Conformal Maps with a free boundary.
//
// B. Lévy, S. Petitjean, N. Ray, J. Maillot, "Least Squares Conformal Maps for Automatic Texture Atlas
// Generation", ACM SIGGRAPH 2002. The conformal energy is written as in Mullen, Tong, Alliez, Desbrun,
// "Spectral Conformal Parameterization", SGP 2008:  E_C(u, v) = 1/2 u^T L u + 1/2 v^T L v - A(u, v),
// L the cotangent Laplacian and A the signed area enclosed by the boundary's image. Two boundary vertices
// far apart are pinned; the symmetric positive definite normal equations are solved by sparse Cholesky.
// The result is scaled about its centroid so its area equals the 3D area, to compare with ARAP.
#include <Eigen/Core>

#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/sparse_cholesky.hpp"

namespace lastcut {

struct LscmResult {
  Eigen::MatrixXd UV;  // #V x 2, mm
  double seconds_factorize = 0;
};

LscmResult lscm(const TriMesh& mesh, const TriangleFrames& frames, const MeshTopology& topology, SparseSolver solver);

}  // namespace lastcut
