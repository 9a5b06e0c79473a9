#include "engine/core/edge_path.hpp"

#include <algorithm>
#include <limits>
#include <queue>
#include <utility>

namespace lastcut {

EdgePath shortest_edge_path(const TriMesh& mesh, const MeshTopology& topology, int from, int to,
                            const std::function<bool(int, int)>& walkable) {
  const auto count = static_cast<std::size_t>(topology.vertex_count());
  std::vector<double> distance(count, std::numeric_limits<double>::infinity());
  std::vector<int> previous(count, -1);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  distance[static_cast<std::size_t>(from)] = 0.0;
  open.emplace(0.0, from);
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    if (u == to) break;
    if (d > distance[static_cast<std::size_t>(u)]) continue;
    for (int i = topology.neighbor_offsets[static_cast<std::size_t>(u)];
         i < topology.neighbor_offsets[static_cast<std::size_t>(u) + 1]; ++i) {
      const int w = topology.neighbors[static_cast<std::size_t>(i)];
      if (walkable && !walkable(u, w)) continue;
      const double through = d + (mesh.V.row(u) - mesh.V.row(w)).norm();
      if (through < distance[static_cast<std::size_t>(w)]) {
        distance[static_cast<std::size_t>(w)] = through;
        previous[static_cast<std::size_t>(w)] = u;
        open.emplace(through, w);
      }
    }
  }
  EdgePath path;
  path.length_mm = distance[static_cast<std::size_t>(to)];
  if (path.length_mm == std::numeric_limits<double>::infinity()) return path;
  for (int v = to; v != -1; v = previous[static_cast<std::size_t>(v)]) path.vertices.push_back(v);
  std::reverse(path.vertices.begin(), path.vertices.end());
  return path;
}

}  // namespace lastcut
