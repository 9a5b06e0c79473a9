#pragma once
// The shortest path between two vertices along a mesh's edges (Dijkstra's algorithm), edge
// lengths in mm. Used where a path must follow the mesh: the contour around a surface region
// (engine/segment/region_contour.hpp) and the surface length the mold quality gate compares a
// mold's span with (engine/scan/mold_quality_gate.hpp).
#include <functional>
#include <vector>

#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"

namespace lastcut {

struct EdgePath {
  double length_mm = 0;       // infinity when `to` cannot be reached
  std::vector<int> vertices;  // from ... to; empty when `to` cannot be reached
};

// mesh: V #V x 3 mm; topology of mesh. walkable(u, w) says whether the edge u-w may be used
// (empty: every edge). Ties are broken the same way on every run.
EdgePath shortest_edge_path(const TriMesh& mesh, const MeshTopology& topology, int from, int to,
                            const std::function<bool(int, int)>& walkable = {});

}  // namespace lastcut
