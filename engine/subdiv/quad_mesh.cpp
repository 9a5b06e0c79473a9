#include "engine/subdiv/quad_mesh.hpp"

#include <algorithm>
#include <string>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

std::string corner_name(int h) { return "quad " + std::to_string(h / 4 + 1); }

void check_corners(const QuadMesh& mesh) {
  const int vertex_count = mesh.vertex_count();
  for (int q = 0; q < mesh.quad_count(); ++q) {
    for (int k = 0; k < 4; ++k) {
      const int v = mesh.Q(q, k);
      if (v < 0 || v >= vertex_count) {
        throw EngineError(corner_name(4 * q) + " refers to vertex " + std::to_string(v + 1) + " of " +
                          std::to_string(vertex_count));
      }
      for (int other = k + 1; other < 4; ++other) {
        if (mesh.Q(q, other) == v) throw EngineError(corner_name(4 * q) + " uses vertex " + std::to_string(v + 1) + " twice");
      }
    }
  }
}

// Pairs the half-edges a->b and b->a through a sort of (min, max, h); refuses crowded or
// inconsistently oriented edges.
void pair_half_edges(const QuadMesh& mesh, QuadTopology& topology) {
  const int half_edges = 4 * mesh.quad_count();
  struct Key {
    int low, high, h;
  };
  std::vector<Key> keys(static_cast<size_t>(half_edges));
  for (int h = 0; h < half_edges; ++h) {
    const int a = mesh.Q(h / 4, h % 4), b = mesh.Q(h / 4, (h + 1) % 4);
    keys[static_cast<size_t>(h)] = {std::min(a, b), std::max(a, b), h};
  }
  std::sort(keys.begin(), keys.end(), [](const Key& x, const Key& y) {
    return x.low != y.low ? x.low < y.low : x.high != y.high ? x.high < y.high : x.h < y.h;
  });
  topology.twin.assign(static_cast<size_t>(half_edges), -1);
  topology.edge_of.assign(static_cast<size_t>(half_edges), -1);
  for (size_t i = 0; i < keys.size();) {
    size_t end = i + 1;
    while (end < keys.size() && keys[end].low == keys[i].low && keys[end].high == keys[i].high) ++end;
    const std::string edge = "edge " + std::to_string(keys[i].low + 1) + "-" + std::to_string(keys[i].high + 1);
    if (end - i > 2) throw EngineError("non-manifold quad mesh: " + edge + " is used by " + std::to_string(end - i) + " faces");
    const int edge_id = topology.edge_count();
    topology.edge_half_edge.push_back(keys[i].h);
    topology.edge_of[static_cast<size_t>(keys[i].h)] = edge_id;
    if (end - i == 2) {
      const int h0 = keys[i].h, h1 = keys[i + 1].h;
      if (mesh.Q(h0 / 4, h0 % 4) == mesh.Q(h1 / 4, h1 % 4)) {
        throw EngineError("quads " + std::to_string(h0 / 4 + 1) + " and " + std::to_string(h1 / 4 + 1) +
                          " disagree on their orientation along " + edge);
      }
      topology.twin[static_cast<size_t>(h0)] = h1;
      topology.twin[static_cast<size_t>(h1)] = h0;
      topology.edge_of[static_cast<size_t>(h1)] = edge_id;
    }
    i = end;
  }
}

}  // namespace

QuadTopology build_quad_topology(const QuadMesh& mesh) {
  if (mesh.V.cols() != 3 || mesh.Q.cols() != 4) throw EngineError("a quad mesh needs #V x 3 positions and #Q x 4 corners");
  check_corners(mesh);
  QuadTopology topology;
  pair_half_edges(mesh, topology);
  const int vertex_count = mesh.vertex_count();
  const int half_edges = 4 * mesh.quad_count();

  // Any outgoing half-edge per vertex, preferring one on the boundary (the start of a boundary fan).
  std::vector<int> start(static_cast<size_t>(vertex_count), -1);
  std::vector<int> corner_count(static_cast<size_t>(vertex_count), 0);
  std::vector<int> boundary_starts(static_cast<size_t>(vertex_count), 0);
  for (int h = 0; h < half_edges; ++h) {
    const auto v = static_cast<size_t>(mesh.Q(h / 4, h % 4));
    ++corner_count[v];
    if (topology.twin[static_cast<size_t>(h)] < 0) {
      ++boundary_starts[v];
      start[v] = h;
    } else if (start[v] < 0) {
      start[v] = h;
    }
  }
  topology.ring_offsets.assign(static_cast<size_t>(vertex_count) + 1, 0);
  topology.on_boundary.assign(static_cast<size_t>(vertex_count), 0);
  topology.ring_position.assign(static_cast<size_t>(half_edges), -1);
  topology.ring.reserve(static_cast<size_t>(half_edges));
  for (int v = 0; v < vertex_count; ++v) {
    const auto vi = static_cast<size_t>(v);
    topology.ring_offsets[vi] = static_cast<int>(topology.ring.size());
    if (boundary_starts[vi] > 1) {
      throw EngineError("non-manifold quad mesh: the faces at vertex " + std::to_string(v + 1) + " touch only at that vertex");
    }
    topology.on_boundary[vi] = boundary_starts[vi] == 1;
    int h = start[vi];
    for (int j = 0; h >= 0 && j <= corner_count[vi]; ++j) {
      if (j > 0 && h == start[vi]) break;
      topology.ring_position[static_cast<size_t>(h)] = j;
      topology.ring.push_back(h);
      h = topology.twin[static_cast<size_t>(prev_half_edge(h))];
    }
    const int fan = static_cast<int>(topology.ring.size()) - topology.ring_offsets[vi];
    if (fan != corner_count[vi]) {
      throw EngineError("non-manifold quad mesh: the " + std::to_string(corner_count[vi]) + " faces at vertex " +
                        std::to_string(v + 1) + " do not form one fan");
    }
  }
  topology.ring_offsets[static_cast<size_t>(vertex_count)] = static_cast<int>(topology.ring.size());
  return topology;
}

}  // namespace lastcut
