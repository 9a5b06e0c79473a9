#pragma once
// Repairs of a scanned triangle soup (mm), each counted in the IntakeReport:
//   merge_duplicate_vertices   vertices closer than 1e-7 of the box diagonal become one
//   remove_degenerate_faces    repeated corners or zero area
//   remove_duplicate_faces     the same three vertices again (either orientation)
//   remove_non_manifold_faces  faces on edges used more than twice, and the smaller fans at
//                              vertices where several fans meet only at the vertex
// Orientation, components and holes follow in mesh_orientation.hpp.
#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"
#include "engine/mesh/read_mesh.hpp"

namespace lastcut {

int merge_duplicate_vertices(TriMesh& mesh);
int remove_degenerate_faces(TriMesh& mesh);
int remove_duplicate_faces(TriMesh& mesh);
// topology: set to the topology of the repaired mesh (built here anyway; the steps after it use it).
int remove_non_manifold_faces(TriMesh& mesh, MeshTopology& topology);

}  // namespace lastcut
