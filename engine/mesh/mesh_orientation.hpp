#pragma once
// The last repair steps on an edge-manifold mesh (after mesh_repair.hpp), counted in the report:
// keep the largest connected piece (refusing when a second piece is large, i.e. the file holds
// several objects), orient all faces consistently and outward (positive signed volume), count the
// holes (boundary loops).
#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"
#include "engine/mesh/read_mesh.hpp"

namespace lastcut {

// Keeps the largest edge-connected piece by area. Throws EngineError("several disconnected
// pieces (N pieces, the second has X% of the largest's area)") when the second piece has more than
// 10% of the largest's area. Pieces smaller than `debris_fraction` of it are counted as loose
// debris; larger removed pieces also get a note. topology: mesh's, rebuilt when pieces go.
void keep_largest_component(TriMesh& mesh, MeshTopology& topology, double debris_fraction, IntakeReport& report);

// Makes neighbouring faces agree, then flips the whole piece if its signed volume is negative.
// Returns the number of faces whose orientation changed. Notes a non-orientable surface.
// topology: mesh's, rebuilt when a face turns.
int orient_outward(TriMesh& mesh, MeshTopology& topology, IntakeReport& report);

// Number of closed chains of boundary edges (holes and open borders).
int count_boundary_loops(const MeshTopology& topology);

// Signed volume (mm^3) enclosed by the faces: positive for a closed outward surface.
double signed_volume_mm3(const TriMesh& mesh);

}  // namespace lastcut
