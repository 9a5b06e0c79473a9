#include "engine/mesh/mesh_face_edits.hpp"

#include <algorithm>
#include <numeric>

namespace lastcut::mesh_detail {

int drop_faces(TriMesh& mesh, const std::vector<char>& removed) {
  Eigen::Index kept = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    if (!removed[static_cast<size_t>(f)]) mesh.F.row(kept++) = mesh.F.row(f);
  const int dropped = static_cast<int>(mesh.F.rows() - kept);
  mesh.F.conservativeResize(kept, 3);
  return dropped;
}

void drop_unreferenced_vertices(TriMesh& mesh) {
  std::vector<int> new_index(static_cast<size_t>(mesh.V.rows()), -1);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) new_index[static_cast<size_t>(mesh.F(f, c))] = 0;
  int count = 0;
  for (int& index : new_index)
    if (index == 0) index = count++;
  Eigen::MatrixXd kept(count, 3);
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    if (new_index[static_cast<size_t>(v)] >= 0) kept.row(new_index[static_cast<size_t>(v)]) = mesh.V.row(v);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) mesh.F(f, c) = new_index[static_cast<size_t>(mesh.F(f, c))];
  mesh.V = std::move(kept);
}

UnionFind::UnionFind(size_t count) : parent_(count) { std::iota(parent_.begin(), parent_.end(), 0); }

int UnionFind::find(int item) {
  while (parent_[static_cast<size_t>(item)] != item) {
    parent_[static_cast<size_t>(item)] = parent_[static_cast<size_t>(parent_[static_cast<size_t>(item)])];
    item = parent_[static_cast<size_t>(item)];
  }
  return item;
}

void UnionFind::unite(int a, int b) {
  a = find(a);
  b = find(b);
  if (a != b) parent_[static_cast<size_t>(std::max(a, b))] = std::min(a, b);
}

}  // namespace lastcut::mesh_detail
