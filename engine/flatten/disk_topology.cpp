// Disk check and boundary loop of a triangle mesh; see disk_topology.hpp.
// Works on per-vertex lists of outgoing half-edges (valence ~6), avoiding hashing or sorting all edges.
#include "engine/flatten/disk_topology.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

int find_root(std::vector<int>& parent, int v) {
  while (parent[v] != v) {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

}  // namespace

DiskTopology check_disk(const TriMesh& mesh) {
  const int vertex_count = mesh.vertex_count();
  const int face_count = mesh.triangle_count();
  if (face_count == 0 || vertex_count < 3) throw EngineError("cannot flatten an empty mesh");
  if (mesh.F.cols() != 3 || mesh.V.cols() != 3) throw EngineError("mesh must have 3D vertices and triangular faces");
  if (!mesh.V.allFinite()) throw EngineError("mesh has non-finite vertex coordinates");

  // Outgoing half-edges per vertex.
  std::vector<int> out_offsets(vertex_count + 1, 0);
  for (int f = 0; f < face_count; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.F(f, k);
      if (v < 0 || v >= vertex_count) {
        throw EngineError("triangle " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                          " which does not exist");
      }
      ++out_offsets[v + 1];
    }
    const int a = mesh.F(f, 0), b = mesh.F(f, 1), c = mesh.F(f, 2);
    if (a == b || b == c || a == c) {
      throw EngineError("triangle " + std::to_string(f) + " repeats a vertex: repair the mesh first");
    }
  }
  std::partial_sum(out_offsets.begin(), out_offsets.end(), out_offsets.begin());
  std::vector<int> out_targets(out_offsets.back());
  {
    std::vector<int> fill(out_offsets.begin(), out_offsets.end() - 1);
    for (int f = 0; f < face_count; ++f) {
      for (int k = 0; k < 3; ++k) out_targets[fill[mesh.F(f, k)]++] = mesh.F(f, (k + 1) % 3);
    }
  }
  auto has_half_edge = [&](int from, int to) {
    for (int i = out_offsets[from]; i < out_offsets[from + 1]; ++i) {
      if (out_targets[i] == to) return true;
    }
    return false;
  };

  std::vector<int> parent(vertex_count);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<int> boundary_next(vertex_count, -1);
  long long half_edge_count = 0, boundary_half_edges = 0;
  for (int v = 0; v < vertex_count; ++v) {
    if (out_offsets[v] == out_offsets[v + 1]) {
      throw EngineError("vertex " + std::to_string(v) + " is not used by any triangle: remove unused vertices first");
    }
    for (int i = out_offsets[v]; i < out_offsets[v + 1]; ++i) {
      const int w = out_targets[i];
      for (int j = i + 1; j < out_offsets[v + 1]; ++j) {
        if (out_targets[j] == w) {
          throw EngineError("edge " + std::to_string(v) + "-" + std::to_string(w) +
                            " is shared by faces of the same orientation: non-manifold or flipped faces");
        }
      }
      ++half_edge_count;
      parent[find_root(parent, v)] = find_root(parent, w);
      if (!has_half_edge(w, v)) {
        if (boundary_next[v] != -1) {
          throw EngineError("vertex " + std::to_string(v) + " is a non-manifold boundary vertex (two boundary fans)");
        }
        boundary_next[v] = w;
        ++boundary_half_edges;
      }
    }
  }
  int components = 0;
  for (int v = 0; v < vertex_count; ++v) components += (find_root(parent, v) == v) ? 1 : 0;
  if (components != 1) {
    throw EngineError("mesh has " + std::to_string(components) + " separate pieces; flatten one piece at a time");
  }
  if (boundary_half_edges == 0) throw EngineError("mesh is a closed surface, not a disk: cut it into halves first");

  DiskTopology topology;
  int start = 0;
  while (boundary_next[start] == -1) ++start;
  for (int v = start;;) {
    topology.boundary_loop.push_back(v);
    v = boundary_next[v];
    if (v == start) break;
    if (static_cast<long long>(topology.boundary_loop.size()) > boundary_half_edges) {
      throw EngineError("mesh boundary does not close into a loop");
    }
  }
  const long long loops_extra = boundary_half_edges - static_cast<long long>(topology.boundary_loop.size());
  if (loops_extra != 0) {
    throw EngineError("mesh has more than one boundary loop (holes): a flattening half must be a disk");
  }
  const long long edge_count = (half_edge_count + boundary_half_edges) / 2;
  const long long euler = vertex_count - edge_count + face_count;
  if (euler != 1) {
    throw EngineError("mesh is not a disk (Euler characteristic " + std::to_string(euler) +
                      ", a disk has 1): it has handles");
  }

  // Symmetric adjacency: outgoing targets plus the boundary half-edges' sources seen from the other side.
  topology.neighbor_offsets.assign(vertex_count + 1, 0);
  for (int v = 0; v < vertex_count; ++v) topology.neighbor_offsets[v + 1] = out_offsets[v + 1] - out_offsets[v];
  // A boundary vertex has one neighbour that is only reachable by an incoming half-edge.
  for (int v = 0; v < vertex_count; ++v) {
    if (boundary_next[v] != -1) ++topology.neighbor_offsets[boundary_next[v] + 1];
  }
  std::partial_sum(topology.neighbor_offsets.begin(), topology.neighbor_offsets.end(), topology.neighbor_offsets.begin());
  topology.neighbors.resize(topology.neighbor_offsets.back());
  std::vector<int> fill(topology.neighbor_offsets.begin(), topology.neighbor_offsets.end() - 1);
  for (int v = 0; v < vertex_count; ++v) {
    for (int i = out_offsets[v]; i < out_offsets[v + 1]; ++i) topology.neighbors[fill[v]++] = out_targets[i];
    if (boundary_next[v] != -1) topology.neighbors[fill[boundary_next[v]]++] = v;
  }
  for (int v = 0; v < vertex_count; ++v) {
    std::sort(topology.neighbors.begin() + topology.neighbor_offsets[v],
              topology.neighbors.begin() + topology.neighbor_offsets[v + 1]);
  }
  return topology;
}

int farthest_vertex_on_loop(const TriMesh& mesh, const std::vector<int>& loop, int from) {
  int best = loop[0];
  double best_sq = -1.0;
  for (int v : loop) {
    const double d = (mesh.V.row(v) - mesh.V.row(from)).squaredNorm();
    if (d > best_sq) {
      best_sq = d;
      best = v;
    }
  }
  return best;
}

}  // namespace lastcut
