#pragma once
// Start map for ARAP with the right global shape: a conformal flattening that keeps the boundary's
// lengths, by Boundary First Flattening with the boundary scale factor u = 0.
//
// R. Sawhney, K. Crane, "Boundary First Flattening", ACM Transactions on Graphics 37(1), 2017,
// sections 4-5: with the cotangent Laplacian A (positive semidefinite), the angle defects Omega at
// interior vertices and the exterior angles k at boundary vertices,
//   1. solve the Dirichlet problem  A_II u_I = -Omega_I,  u_B = 0     (the log scale that makes the
//      interior flat while the boundary keeps its lengths; u < 0 where the surface has more area
//      than a flat disk could hold),
//   2. the flat boundary's exterior angles are  k~ = k + (A u)_B  (the Dirichlet-to-Neumann map; they
//      sum to 2 pi by the discrete Gauss-Bonnet theorem),
//   3. integrate k~ into a polygon with the boundary's edge lengths, closed by the least change of the
//      lengths in the 1/length-weighted norm (the paper's closing step, a 2x2 system),
//   4. extend the polygon into the interior harmonically (A_II x_I = -A_IB x_B, both coordinates; the
//      paper's simpler variant of the extension).
// Both solves use one factorization of A with the boundary rows fixed.
//
// Why not the plane-rotation start (plane_rotation_start.hpp): on a half that wraps around the foot it
// lays opposite sides of the surface with inconsistent rotations, and ARAP then needs hundreds of
// iterations to unroll it (measured on the FIND foot halves: 200 iterations and the outline still 20 mm
// from the converged map, docs/benchmarks-flatten.md). This map has the unrolled shape from the start.
#include <Eigen/Core>

#include "engine/core/tri_mesh.hpp"
#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/sparse_cholesky.hpp"

namespace lastcut {

// UV #V x 2, mm, counter-clockwise, not flip-free in general (obtuse triangles near the boundary can
// fold in the harmonic extension; ARAP and its repair take it from there).
// laplacian: a copy of the ARAP pattern (its matrix is overwritten with the fixed-boundary system);
// solver: has analysed that pattern, and is left holding the factor of the fixed-boundary system.
// Throws EngineError when the mesh has no boundary loop.
Eigen::MatrixXd boundary_first_start(const TriMesh& mesh, const TriangleFrames& frames, const MeshTopology& topology,
                                     ReducedLaplacian& laplacian, SparseCholesky& solver);

}  // namespace lastcut
