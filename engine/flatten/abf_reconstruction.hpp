#pragma once
// ABF++ step 2: the 2D map from the corner angles, by least squares.
//
// A. Sheffer, B. Lévy, M. Mogilnitsky, A. Bogomyakov, "ABF++: Fast and Robust Angle Based Flattening",
// ACM Transactions on Graphics 24(2), 2005, section 5 (the LSCM-like reconstruction): in a triangle
// (a, b, c) with angles alpha_a, alpha_b, alpha_c, the edge a->c is the edge a->b turned counter-clockwise
// by alpha_a and scaled by sin(alpha_b) / sin(alpha_c) (law of sines). These 2 linear equations per
// triangle, over all triangles, with two far-apart boundary vertices pinned, are solved in the
// least-squares sense (normal equations, sparse Cholesky). Each triangle's corners are rotated so that c
// has the largest sine (the division is the best conditioned). With consistent angles (every ABF
// constraint met) the equations have an exact solution: the map then has the angles exactly.
// The result is scaled about its centroid so that its area equals the 3D area (the angles fix the map
// only up to a similarity), as LSCM's is (lscm.hpp).
#include <Eigen/Core>
#include <vector>

#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"
#include "engine/flatten/sparse_cholesky.hpp"

namespace lastcut {

// mesh: the 3D disk (mm) with topology checked; alpha: 3 #F corner angles (rad, in (0, pi)).
// Returns UV #V x 2, mm, total signed area = the 3D area. Throws EngineError if the map degenerates.
Eigen::MatrixXd reconstruct_from_angles(const TriMesh& mesh, const MeshTopology& topology,
                                        const std::vector<double>& alpha, SparseSolver solver = SparseSolver::Auto);

}  // namespace lastcut
