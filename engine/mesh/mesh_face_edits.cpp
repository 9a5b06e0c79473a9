#include "engine/mesh/mesh_edges.hpp"

#include <algorithm>
#include <numeric>

namespace lastcut::mesh_detail {

FaceAdjacency face_adjacency(const TriMesh& mesh, const std::vector<char>& removed) {
  const size_t face_count = static_cast<size_t>(mesh.F.rows());
  const size_t vertex_count = static_cast<size_t>(mesh.V.rows());
  auto is_removed = [&removed](size_t f) { return !removed.empty() && removed[f]; };
  // Vertex stars in compressed rows: star_faces[star_begin[v] .. star_begin[v + 1]).
  std::vector<int> star_begin(vertex_count + 1, 0);
  for (size_t f = 0; f < face_count; ++f)
    if (!is_removed(f))
      for (int c = 0; c < 3; ++c) ++star_begin[static_cast<size_t>(mesh.F(static_cast<Eigen::Index>(f), c)) + 1];
  for (size_t v = 0; v < vertex_count; ++v) star_begin[v + 1] += star_begin[v];
  std::vector<int> fill(star_begin.begin(), star_begin.end() - 1);
  std::vector<int> star_faces(static_cast<size_t>(star_begin.back()));
  for (size_t f = 0; f < face_count; ++f)
    if (!is_removed(f))
      for (int c = 0; c < 3; ++c) star_faces[static_cast<size_t>(fill[static_cast<size_t>(mesh.F(static_cast<Eigen::Index>(f), c))]++)] = static_cast<int>(f);

  FaceAdjacency adjacency;
  adjacency.neighbour.assign(3 * face_count, kBoundaryEdge);
  adjacency.same_direction.assign(3 * face_count, 0);
  adjacency.neighbour_corner.assign(3 * face_count, -1);
  for (size_t f = 0; f < face_count; ++f) {
    if (is_removed(f)) continue;
    const Eigen::Index row = static_cast<Eigen::Index>(f);
    for (int c = 0; c < 3; ++c) {
      const int a = mesh.F(row, c), b = mesh.F(row, (c + 1) % 3);
      int found = kBoundaryEdge;
      for (int k = star_begin[static_cast<size_t>(a)]; k < star_begin[static_cast<size_t>(a) + 1]; ++k) {
        const int g = star_faces[static_cast<size_t>(k)];
        if (g == static_cast<int>(f)) continue;
        const Eigen::Index other = static_cast<Eigen::Index>(g);
        int corner_a = -1, corner_b = -1;
        for (int d = 0; d < 3; ++d) {
          if (mesh.F(other, d) == a) corner_a = d;
          if (mesh.F(other, d) == b) corner_b = d;
        }
        if (corner_b < 0) continue;
        if (found != kBoundaryEdge) {
          found = kCrowdedEdge;
          break;
        }
        found = g;
        adjacency.same_direction[3 * f + static_cast<size_t>(c)] = (corner_a + 1) % 3 == corner_b;
        adjacency.neighbour_corner[3 * f + static_cast<size_t>(c)] = corner_a;
      }
      adjacency.neighbour[3 * f + static_cast<size_t>(c)] = found;
    }
  }
  return adjacency;
}

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
