#pragma once
// The edge table of a triangle soup, shared by the repair steps: every face corner's directed
// edge, sorted so that the uses of one undirected edge are adjacent. Internal to engine/mesh.
#include <cstdint>
#include <vector>

#include "engine/core/tri_mesh.hpp"

namespace lastcut::mesh_detail {

struct EdgeUse {
  uint64_t key;   // (min vertex << 32) | max vertex
  int face;
  int corner;     // the edge runs from corner to corner + 1 (mod 3)
  bool forward;   // true when it runs from the smaller to the larger vertex index
};

// All 3 #F edge uses of the faces not flagged in `removed` (empty: none removed), sorted by key.
std::vector<EdgeUse> sorted_edge_uses(const TriMesh& mesh, const std::vector<char>& removed);

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
