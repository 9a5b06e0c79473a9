#pragma once
// Per-triangle isometric 2D frames, cotangent weights, and fast assembly of the cotangent Laplacian
// into a fixed sparsity pattern with one pinned vertex removed.
//
// Cotangent weights: U. Pinkall, K. Polthier, "Computing discrete minimal surfaces and their conjugates",
// Experimental Mathematics 2(1), 1993. The weight of the edge opposite corner k of a triangle is
// cot(angle_k) / 2, so that sum_edges w (u_i - u_j)^2 is the Dirichlet energy of the piecewise linear u.
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "engine/core/tri_mesh.hpp"
#include "engine/flatten/disk_topology.hpp"

namespace lastcut {

// Edge k of triangle (v0, v1, v2) runs from v[k+1] to v[k+2] (indices mod 3) and is opposite corner k.
struct TriangleFrames {
  std::vector<std::array<int, 3>> triangles;  // #F vertex ids
  std::vector<double> half_weight;            // 3 #F: cot(angle_k) / 2
  std::vector<double> edge_local_mm;          // 6 #F: edge k in the triangle's own isometric 2D frame (x, y)
  Eigen::VectorXd area_mm2;                   // #F
};

// Throws EngineError for a zero-area triangle (it has no isometric frame).
TriangleFrames compute_triangle_frames(const TriMesh& mesh);

// The Laplacian's pattern on all vertices but `pinned`, with the value slot of every triangle entry.
struct ReducedLaplacian {
  int pinned = -1;
  std::vector<int> row_of_vertex;     // #V, -1 for the pinned vertex
  std::vector<int> vertex_of_row;     // #V - 1
  Eigen::SparseMatrix<double> matrix;  // (#V-1) x (#V-1), both triangles stored
  // 9 #F value slots: diagonal of corners 0..2, then (row v[k+1], col v[k+2]) and its transpose per edge k;
  // -1 where the entry involves the pinned vertex.
  std::vector<int> slot;
};

ReducedLaplacian build_reduced_pattern(const TriangleFrames& frames, const MeshTopology& topology, int pinned);

// Writes sum_edges w (u_i - u_j)^2 into `laplacian.matrix` from per-half-edge weights (3 #F).
// Rows of vertices with fixed[v] != 0 become identity rows and their couplings are left at zero (the caller
// moves them to the right-hand side); the pattern is kept, so one symbolic analysis serves every assembly.
void assemble_laplacian(const TriangleFrames& frames, const std::vector<double>& half_weight,
                        const std::vector<char>& fixed, ReducedLaplacian& laplacian);

// The free-boundary ARAP system: the cotangent Laplacian (frames.half_weight) with the first vertex of the
// boundary loop pinned, so the system is definite; returns the assembled (#V-1) x (#V-1) matrix.
ReducedLaplacian pinned_cotangent_laplacian(const TriangleFrames& frames, const MeshTopology& topology);

}  // namespace lastcut
