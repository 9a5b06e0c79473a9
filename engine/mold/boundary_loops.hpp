#pragma once
// Boundary loops of a triangle mesh: the closed chains of edges that belong to one triangle only.
#include <Eigen/Core>
#include <vector>

namespace lastcut {

// F #F x 3. Returns each boundary loop as vertex indices in the order the boundary edges run
// (the orientation of the faces: for a CCW-in-UV patch the loop is CCW). Loops are sorted by
// decreasing number of vertices. Throws EngineError when a boundary vertex has more than one
// outgoing boundary edge (the patch is not a manifold with boundary).
std::vector<std::vector<int>> boundary_loops(const Eigen::MatrixXi& F);

}  // namespace lastcut
