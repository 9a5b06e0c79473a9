#pragma once
// Scan holes as a scanner leaves them, cut into a test mesh: ragged star-shaped outlines (nine lobes,
// radius 50-100 %, on top of the triangles' own staircase) whose perimeter is far longer than pi
// times their size across. Shared by tests/scan and tests/cli_flatten.
#include <Eigen/Core>
#include <vector>

#include "engine/core/tri_mesh.hpp"

namespace lastcut::test {

struct HoleSpec {
  Eigen::Vector3d near_mm;  // the hole is centred on the vertex nearest this point
  double across_mm;         // its outer size across (the outline reaches about this far, whole triangles)
};

// mesh: V #V x 3 mm, F #F x 3, closed. Removes the faces inside each hole's outline, then the faces at
// pinches and every island but the largest piece, so each hole is one boundary loop. Unreferenced
// vertices are dropped.
TriMesh with_ragged_holes(const TriMesh& mesh, const std::vector<HoleSpec>& holes);

// Hole centres on a last in the canonical frame (+X heel to toe, +Z up): on its sides, half way up,
// at 25 %, 50 %, 75 % ... of its length, alternately on +Y and -Y, one per size in across_mm.
std::vector<HoleSpec> side_holes(const TriMesh& last, const std::vector<double>& across_mm);

}  // namespace lastcut::test
