#pragma once
// Checks that a triangle mesh is a topological disk (connected, manifold, consistently oriented,
// exactly one boundary loop, Euler characteristic 1) and returns its boundary loop and vertex adjacency.
// Flattening needs a disk: a closed surface or one with holes has no single outline to cut.
#include <vector>

#include "engine/core/tri_mesh.hpp"

namespace lastcut {

struct DiskTopology {
  // Boundary vertices in order, with the mesh interior on the left when the faces are seen
  // counter-clockwise (so laying them counter-clockwise on a convex curve keeps the triangles' orientation).
  std::vector<int> boundary_loop;
  // Vertex adjacency in compressed rows: neighbours of v are neighbors[neighbor_offsets[v] .. [v+1]), sorted.
  std::vector<int> neighbor_offsets;  // #V + 1
  std::vector<int> neighbors;         // 2 #E
};

// Throws EngineError with one line naming the first problem found (out-of-range index, unused vertex,
// degenerate face, edge shared by more than two faces or flipped neighbours, several components,
// no boundary, holes).
DiskTopology check_disk(const TriMesh& mesh);

// The vertex of `loop` (non-empty vertex indices) farthest in 3D from vertex `from`: used to pick
// far-apart boundary vertices (LSCM pins, the start map's long axis).
int farthest_vertex_on_loop(const TriMesh& mesh, const std::vector<int>& loop, int from);

}  // namespace lastcut
