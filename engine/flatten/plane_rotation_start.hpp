#pragma once
// Start map for ARAP that costs no factorization of its own: one ARAP global step with the rotations
// taken from the surface itself instead of from a previous map.
//
// Each triangle is turned by the smallest rotation that takes its normal to the half's mean normal N
// (area-weighted), then laid in the plane normal to N: an isometric copy of the triangle, with the
// orientations of neighbouring triangles agreeing wherever the surface bends about one axis (exactly the
// development on a cylinder patch, close to it on a cone patch: tests/flatten/plane_start_test.cpp). Solving the ARAP Laplacian against those
// triangle edges (Liu et al. 2008, global step) stitches them into a map near the developed shape, so ARAP
// needs fewer iterations than from a convex start, and the Laplacian's factorization, already needed by
// ARAP, is the only one made. Unlike the Tutte embedding (tutte_embedding.hpp) this map is not guaranteed
// flip-free; flatten() checks the result and keeps the Tutte map as the fallback.
#include <Eigen/Core>
#include <optional>

#include "engine/core/tri_mesh.hpp"
#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/sparse_cholesky.hpp"

namespace lastcut {

// UV #V x 2, mm, the pinned vertex at the origin, u along the outline's longest chord. `laplacian` holds the ARAP cotangent Laplacian pinned at
// laplacian.pinned and `factor` its factorization. Empty when the half has no mean direction (its area-
// weighted normals cancel out, as on a nearly closed surface): the caller then starts from the Tutte
// embedding. Triangles facing almost straight away from N are turned half a turn and projected.
// Share of the surface area (0..1) whose triangles face away from the area-weighted mean normal (normal
// at more than 90 degrees to it): where there is such area the half wraps around and this start lays
// it rolled up. 1 when the normals cancel out.
double area_facing_away_share(const TriMesh& mesh);

std::optional<Eigen::MatrixXd> plane_rotation_start(const TriMesh& mesh, const TriangleFrames& frames,
                                                    const MeshTopology& topology, const ReducedLaplacian& laplacian,
                                                    const SparseCholesky& factor);

}  // namespace lastcut
