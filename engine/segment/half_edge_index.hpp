#pragma once
// Half-edges of a triangle mesh grouped by their start vertex (compressed rows), so that the twin
// of a half-edge a -> b is found by scanning b's few outgoing half-edges: linear time, no hashing,
// no global sort. Shared by the graph, hole filling and half extraction steps.
#include <Eigen/Core>
#include <vector>

namespace lastcut {

struct HalfEdgeIndex {
  std::vector<int> offsets;  // #V + 1: half-edges leaving v are entries offsets[v] .. offsets[v+1]
  std::vector<int> target;   // end vertex of each half-edge
  std::vector<int> corner;   // 3 * face + k for the half-edge F(f,k) -> F(f,(k+1)%3)

  // Entry of the half-edge from -> to, or -1 when the mesh has none.
  int find(int from, int to) const {
    for (int i = offsets[static_cast<std::size_t>(from)]; i < offsets[static_cast<std::size_t>(from) + 1]; ++i)
      if (target[static_cast<std::size_t>(i)] == to) return i;
    return -1;
  }
};

// F #F x 3 with indices below vertex_count.
inline HalfEdgeIndex build_half_edge_index(const Eigen::MatrixXi& F, Eigen::Index vertex_count) {
  HalfEdgeIndex index;
  index.offsets.assign(static_cast<std::size_t>(vertex_count) + 1, 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) ++index.offsets[static_cast<std::size_t>(F(f, k)) + 1];
  for (std::size_t v = 0; v + 1 < index.offsets.size(); ++v) index.offsets[v + 1] += index.offsets[v];
  index.target.resize(static_cast<std::size_t>(F.rows()) * 3);
  index.corner.resize(static_cast<std::size_t>(F.rows()) * 3);
  std::vector<int> fill(index.offsets.begin(), index.offsets.end() - 1);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto slot = static_cast<std::size_t>(fill[static_cast<std::size_t>(F(f, k))]++);
      index.target[slot] = F(f, (k + 1) % 3);
      index.corner[slot] = static_cast<int>(3 * f + k);
    }
  return index;
}

}  // namespace lastcut
