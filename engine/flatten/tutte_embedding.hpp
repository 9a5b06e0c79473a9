#pragma once
// Flip-free starting map for ARAP: a convex-combination (Tutte) embedding with the boundary on an ellipse.
//
// W. T. Tutte, "How to draw a graph", Proc. London Math. Soc. 13, 1963; M. S. Floater, "Parametrization
// and smooth approximation of surface triangulations", CAGD 14(3), 1997: with the boundary on a strictly
// convex curve and every interior vertex a convex combination (positive weights) of its neighbours,
// the map is a bijection with no flipped triangle. We use the cotangent weights clamped to be positive,
// which is harmonic (close to conformal) on well-shaped meshes and still guaranteed flip-free, and an
// ellipse whose long axis joins the two boundary vertices farthest apart in 3D and whose size matches
// the boundary length and surface area, so that ARAP starts near the developed shape.
#include <Eigen/Core>

#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/sparse_cholesky.hpp"

namespace lastcut {

// UV #V x 2, mm. `laplacian` must be pinned at a boundary vertex; `solver` must have analysed its pattern.
// The solver is left holding the factor of the embedding's matrix.
Eigen::MatrixXd tutte_embedding(const TriMesh& mesh, const TriangleFrames& frames, const MeshTopology& topology,
                                ReducedLaplacian& laplacian, SparseCholesky& solver);

// Positions of the boundary loop on the ellipse described above (#boundary x 2, mm, counter-clockwise).
Eigen::MatrixXd boundary_on_ellipse(const TriMesh& mesh, const std::vector<int>& boundary_loop, double area_mm2);

}  // namespace lastcut
