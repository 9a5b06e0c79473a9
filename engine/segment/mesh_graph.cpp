#include "engine/segment/mesh_graph.hpp"

#include <algorithm>

#include "engine/segment/half_edge_index.hpp"

namespace lastcut {

MeshGraph build_mesh_graph(const TriMesh& mesh) {
  const HalfEdgeIndex index = build_half_edge_index(mesh.F, mesh.V.rows());
  const auto vertex_count = static_cast<std::size_t>(mesh.V.rows());
  MeshGraph graph;
  graph.face_neighbors = Eigen::MatrixXi::Constant(mesh.F.rows(), 3, -1);
  // Neighbours of v: the ends of its outgoing half-edges, plus the starts of incoming boundary
  // half-edges (on a boundary the last neighbour has no half-edge back to it).
  std::vector<std::pair<int, int>> boundary_incoming;  // (vertex, neighbour)
  for (std::size_t from = 0; from < vertex_count; ++from)
    for (int i = index.offsets[from]; i < index.offsets[from + 1]; ++i) {
      const int to = index.target[static_cast<std::size_t>(i)];
      const int twin = index.find(to, static_cast<int>(from));
      const int c = index.corner[static_cast<std::size_t>(i)];
      if (twin >= 0)
        graph.face_neighbors(c / 3, c % 3) = index.corner[static_cast<std::size_t>(twin)] / 3;
      else
        boundary_incoming.emplace_back(to, static_cast<int>(from));
    }
  std::sort(boundary_incoming.begin(), boundary_incoming.end());
  graph.neighbor_offsets.assign(vertex_count + 1, 0);
  graph.neighbors.reserve(index.target.size() + boundary_incoming.size());
  auto incoming = boundary_incoming.begin();
  for (std::size_t v = 0; v < vertex_count; ++v) {
    const auto row_begin = static_cast<std::ptrdiff_t>(graph.neighbors.size());
    graph.neighbors.insert(graph.neighbors.end(), index.target.begin() + index.offsets[v],
                           index.target.begin() + index.offsets[v + 1]);
    for (; incoming != boundary_incoming.end() && incoming->first == static_cast<int>(v); ++incoming)
      graph.neighbors.push_back(incoming->second);
    std::sort(graph.neighbors.begin() + row_begin, graph.neighbors.end());
    graph.neighbors.erase(std::unique(graph.neighbors.begin() + row_begin, graph.neighbors.end()), graph.neighbors.end());
    graph.neighbor_offsets[v + 1] = static_cast<int>(graph.neighbors.size());
  }
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
