#pragma once
// Edge adjacency of a triangle soup, shared by the repair steps (internal to engine/mesh).
// Built from the vertex stars (faces around each vertex), so no global sort of all edges:
// O(#F x valence), the reason 400k-triangle scans repair in a fraction of a second.
#include <vector>

#include "engine/core/tri_mesh.hpp"

namespace lastcut::mesh_detail {

constexpr int kBoundaryEdge = -1;  // no other face on the edge
constexpr int kCrowdedEdge = -2;   // two or more other faces on the edge (non-manifold)

struct FaceAdjacency {
  // Per face corner 3 f + c, for the edge from F(f, c) to F(f, (c + 1) % 3):
  std::vector<int> neighbour;           // the one other face, kBoundaryEdge or kCrowdedEdge
  std::vector<char> same_direction;     // that face runs the edge the same way (inconsistent orientation)
  std::vector<int> neighbour_corner;    // the corner of F(f, c) in the neighbour face
};

// Faces flagged in `removed` (may be empty: none) are ignored and have no neighbours.
FaceAdjacency face_adjacency(const TriMesh& mesh, const std::vector<char>& removed);

// Keeps the faces not flagged; returns how many were dropped.
int drop_faces(TriMesh& mesh, const std::vector<char>& removed);
// Drops vertices no face uses and renumbers the faces.
void drop_unreferenced_vertices(TriMesh& mesh);

class UnionFind {
 public:
  explicit UnionFind(size_t count);
  int find(int item);
  void unite(int a, int b);

 private:
  std::vector<int> parent_;
};

}  // namespace lastcut::mesh_detail
