#pragma once
// The outline loops of a patch: its boundary loops (engine/core/mesh_topology.hpp), refused when
// they do not form simple closed loops, largest first.
#include <vector>

#include "engine/core/mesh_topology.hpp"

namespace lastcut {

// Each boundary loop as vertex indices in the order the boundary edges run (the orientation of
// the faces: for a CCW-in-UV patch the loop is CCW), sorted by decreasing number of vertices.
// Throws EngineError when a boundary vertex has more than one outgoing boundary edge or a chain of
// boundary edges does not close (the patch is not a manifold with boundary).
std::vector<std::vector<int>> simple_boundary_loops(const MeshTopology& topology);

}  // namespace lastcut
