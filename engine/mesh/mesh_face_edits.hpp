#pragma once
// Dropping faces and unused vertices during repair, and the union-find the repair steps group
// corners with (internal to engine/mesh). Connectivity comes from engine/core/mesh_topology.hpp.
#include <vector>

#include "engine/core/tri_mesh.hpp"

namespace lastcut::mesh_detail {

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
