#pragma once
// Topology and geometry measurements the lastgen tests assert on, computed independently of the
// generator (plain index arithmetic, no OpenMesh), so a bug in the generator's tools cannot hide.
#include <Eigen/Geometry>
#include <vector>

#include "engine/core/tri_mesh.hpp"

namespace lastcut::test {

struct EdgeCensus {
  int boundary_edges = 0;       // edges with one face
  int non_manifold_edges = 0;   // edges with more than two faces
  int inconsistent_edges = 0;   // interior edges whose two faces run the same direction
  int boundary_loops = 0;       // closed chains of boundary edges
  std::vector<std::vector<int>> loop_vertices;  // the vertices of each chain
};
EdgeCensus edge_census(const TriMesh& mesh);

// Signed volume (mm^3): positive when the faces are outward and the surface closed.
double signed_volume_mm3(const TriMesh& mesh);
// V - E + F.
int euler_characteristic(const TriMesh& mesh);
// Smallest 4 sqrt(3) area / (sum of squared edges) over all triangles: 1 equilateral, 0 sliver.
double worst_triangle_quality(const TriMesh& mesh);

}  // namespace lastcut::test
