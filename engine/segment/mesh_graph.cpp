#include "engine/segment/mesh_graph.hpp"

#include <algorithm>
#include <cstdint>

namespace lastcut {

MeshGraph build_mesh_graph(const TriMesh& mesh) {
  const Eigen::Index face_count = mesh.F.rows();
  struct HalfEdge {
    std::uint64_t key;  // (smaller vertex, larger vertex)
    int corner;         // 3 * face + k
  };
  std::vector<HalfEdge> half_edges;
  half_edges.reserve(static_cast<std::size_t>(face_count) * 3);
  for (Eigen::Index f = 0; f < face_count; ++f)
    for (int k = 0; k < 3; ++k) {
      const auto a = static_cast<std::uint32_t>(mesh.F(f, k)), b = static_cast<std::uint32_t>(mesh.F(f, (k + 1) % 3));
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
      half_edges.push_back({key, static_cast<int>(3 * f + k)});
    }
  std::sort(half_edges.begin(), half_edges.end(),
            [](const HalfEdge& x, const HalfEdge& y) { return x.key != y.key ? x.key < y.key : x.corner < y.corner; });

  MeshGraph graph;
  graph.face_neighbors = Eigen::MatrixXi::Constant(face_count, 3, -1);
  const auto vertex_count = static_cast<std::size_t>(mesh.V.rows());
  std::vector<int> degree(vertex_count, 0);
  std::vector<std::pair<int, int>> edges;
  edges.reserve(half_edges.size() / 2 + 1);
  for (std::size_t i = 0; i < half_edges.size();) {
    std::size_t j = i;
    while (j < half_edges.size() && half_edges[j].key == half_edges[i].key) ++j;
    if (j - i == 2) {  // manifold interior edge; boundary and non-manifold edges keep -1
      const int c0 = half_edges[i].corner, c1 = half_edges[i + 1].corner;
      graph.face_neighbors(c0 / 3, c0 % 3) = c1 / 3;
      graph.face_neighbors(c1 / 3, c1 % 3) = c0 / 3;
    }
    const int a = static_cast<int>(half_edges[i].key >> 32), b = static_cast<int>(half_edges[i].key & 0xffffffffu);
    edges.emplace_back(a, b);
    ++degree[static_cast<std::size_t>(a)];
    ++degree[static_cast<std::size_t>(b)];
    i = j;
  }
  graph.neighbor_offsets.assign(vertex_count + 1, 0);
  for (std::size_t v = 0; v < vertex_count; ++v) graph.neighbor_offsets[v + 1] = graph.neighbor_offsets[v] + degree[v];
  graph.neighbors.resize(static_cast<std::size_t>(graph.neighbor_offsets[vertex_count]));
  std::vector<int> fill(graph.neighbor_offsets.begin(), graph.neighbor_offsets.end() - 1);
  for (const auto& [a, b] : edges) {
    graph.neighbors[static_cast<std::size_t>(fill[static_cast<std::size_t>(a)]++)] = b;
    graph.neighbors[static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++)] = a;
  }
  for (std::size_t v = 0; v < vertex_count; ++v)
    std::sort(graph.neighbors.begin() + graph.neighbor_offsets[v], graph.neighbors.begin() + graph.neighbor_offsets[v + 1]);
  return graph;
}

std::vector<int> face_components(const MeshGraph& graph, const std::vector<char>& in_set, int& component_count) {
  const auto face_count = static_cast<int>(graph.face_neighbors.rows());
  std::vector<int> component(static_cast<std::size_t>(face_count), -1);
  std::vector<int> stack;
  component_count = 0;
  for (int seed = 0; seed < face_count; ++seed) {
    if (!in_set[static_cast<std::size_t>(seed)] || component[static_cast<std::size_t>(seed)] >= 0) continue;
    component[static_cast<std::size_t>(seed)] = component_count;
    stack.push_back(seed);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int g = graph.face_neighbors(f, k);
        if (g < 0 || !in_set[static_cast<std::size_t>(g)] || component[static_cast<std::size_t>(g)] >= 0) continue;
        component[static_cast<std::size_t>(g)] = component_count;
        stack.push_back(g);
      }
    }
    ++component_count;
  }
  return component;
}

std::vector<double> component_areas(const std::vector<int>& component, int component_count, const Eigen::VectorXd& areas) {
  std::vector<double> sums(static_cast<std::size_t>(component_count), 0.0);
  for (std::size_t f = 0; f < component.size(); ++f)
    if (component[f] >= 0) sums[static_cast<std::size_t>(component[f])] += areas(static_cast<Eigen::Index>(f));
  return sums;
}

}  // namespace lastcut
