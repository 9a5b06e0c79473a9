#pragma once
// Checks that a triangle mesh is a topological disk (connected, manifold, consistently oriented,
// exactly one boundary loop, Euler characteristic 1). Flattening needs a disk: a closed surface or
// one with holes has no single outline to cut. The flattening steps then read the boundary loop
// (MeshTopology::boundary_loops[0], interior on the left for counter-clockwise faces) and the
// sorted vertex neighbours from the checked topology.
#include <vector>

#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"

namespace lastcut {

// mesh: V #V x 3 mm, F #F x 3; topology: build_mesh_topology(mesh.F, mesh.V.rows()).
// Throws EngineError with one line naming the first problem found (unused vertex, degenerate face,
// edge shared by more than two faces or flipped neighbours, several components, no boundary, holes).
void check_disk(const TriMesh& mesh, const MeshTopology& topology);

// Builds the mesh's topology (also refusing out-of-range indices) and checks it as above.
MeshTopology check_disk(const TriMesh& mesh);

// The vertex of `loop` (non-empty vertex indices) farthest in 3D from vertex `from`: used to pick
// far-apart boundary vertices (LSCM pins, the start map's long axis).
int farthest_vertex_on_loop(const TriMesh& mesh, const std::vector<int>& loop, int from);

}  // namespace lastcut
