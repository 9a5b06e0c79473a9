// Mesh connectivity from half-edges grouped by start vertex; see mesh_topology.hpp.
#include "engine/core/mesh_topology.hpp"

#include <algorithm>
#include <string>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

using Index = std::size_t;

Index at(int i) { return static_cast<Index>(i); }

void group_by_start_vertex(const Eigen::MatrixXi& F, Eigen::Index vertex_count, const std::vector<char>& ignored,
                           MeshTopology& t) {
  auto kept = [&ignored](Eigen::Index f) { return ignored.empty() || !ignored[static_cast<Index>(f)]; };
  t.out_offsets.assign(static_cast<Index>(vertex_count) + 1, 0);
  t.across.assign(3 * static_cast<Index>(F.rows()), kBoundaryEdge);
  t.same_direction.assign(t.across.size(), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    if (!kept(f)) continue;
    for (int k = 0; k < 3; ++k) {
      const int v = F(f, k);
      if (v < 0 || v >= vertex_count)
        throw EngineError("triangle " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                          " which does not exist");
      ++t.out_offsets[at(v) + 1];
    }
  }
  for (Index v = 0; v + 1 < t.out_offsets.size(); ++v) t.out_offsets[v + 1] += t.out_offsets[v];
  t.out_half_edges.resize(at(t.out_offsets.back()));
  t.out_targets.resize(at(t.out_offsets.back()));
  std::vector<int> fill(t.out_offsets.begin(), t.out_offsets.end() - 1);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    if (!kept(f)) continue;
    for (int k = 0; k < 3; ++k) {
      const Index slot = at(fill[at(F(f, k))]++);
      t.out_half_edges[slot] = static_cast<int>(3 * f + k);
      t.out_targets[slot] = F(f, (k + 1) % 3);
    }
  }
}

// Per entry of the compressed rows (not per half-edge), read in row order while building.
struct SlotFlags {
  std::vector<char> paired;       // the edge of this entry is settled
  std::vector<char> no_way_back;  // no half-edge runs this entry's edge the other way
  std::vector<char> boundary;     // the entry's edge has no other face
  bool repeated_edges = false;    // some edge has more than two half-edges or two the same way
};

// Every edge is settled once, from its first entry met: the entries leaving `from` towards `to`
// run the same way, those leaving `to` towards `from` run against it. Each edge thus costs one look
// at its two vertices' few half-edges.
SlotFlags pair_half_edges(MeshTopology& t) {
  const std::size_t slots = t.out_half_edges.size();
  SlotFlags flags{std::vector<char>(slots, 0), std::vector<char>(slots, 0), std::vector<char>(slots, 0), false};
  const int vertex_count = t.vertex_count();
  for (int from = 0; from < vertex_count; ++from) {
    const int row_end = t.out_offsets[at(from) + 1];
    for (int i = t.out_offsets[at(from)]; i < row_end; ++i) {
      if (flags.paired[at(i)]) continue;
      const int to = t.out_targets[at(i)];
      const int back_begin = t.out_offsets[at(to)], back_end = t.out_offsets[at(to) + 1];
      int same_count = 0, same_slot = -1, back_count = 0, back_slot = -1;
      for (int j = i + 1; j < row_end; ++j)
        if (t.out_targets[at(j)] == to) ++same_count, same_slot = j;
      for (int j = back_begin; j < back_end; ++j)
        if (t.out_targets[at(j)] == from) ++back_count, back_slot = j;
      const int h = t.out_half_edges[at(i)];
      flags.paired[at(i)] = 1;
      if (same_count + back_count == 0) {
        t.across[at(h)] = kBoundaryEdge;
        flags.boundary[at(i)] = flags.no_way_back[at(i)] = 1;
        ++t.boundary_half_edges;
      } else if (same_count + back_count == 1) {
        const int other_slot = same_count == 1 ? same_slot : back_slot;
        const int other = t.out_half_edges[at(other_slot)];
        t.across[at(h)] = other;
        t.across[at(other)] = h;
        t.same_direction[at(h)] = t.same_direction[at(other)] = same_count == 1;
        flags.paired[at(other_slot)] = 1;
        flags.no_way_back[at(i)] = flags.no_way_back[at(other_slot)] = same_count == 1;
        flags.repeated_edges = flags.repeated_edges || same_count == 1;
      } else {
        flags.repeated_edges = true;
        t.across[at(h)] = kCrowdedEdge;
        flags.no_way_back[at(i)] = back_count == 0;
        for (int j = i + 1; j < row_end; ++j)
          if (t.out_targets[at(j)] == to) {
            t.across[at(t.out_half_edges[at(j)])] = kCrowdedEdge;
            flags.paired[at(j)] = 1;
            flags.no_way_back[at(j)] = back_count == 0;
          }
        for (int j = back_begin; j < back_end; ++j)
          if (t.out_targets[at(j)] == from) {
            t.across[at(t.out_half_edges[at(j)])] = kCrowdedEdge;
            flags.paired[at(j)] = 1;
          }
      }
    }
  }
  return flags;
}

// Neighbours of v: the ends of its half-edges, and the starts of incoming half-edges that have no
// half-edge back (on a boundary, or against a neighbour of the other orientation).
void collect_neighbours(const SlotFlags& flags, MeshTopology& t) {
  const Index vertex_count = at(t.vertex_count());
  t.neighbor_offsets.assign(vertex_count + 1, 0);
  for (Index from = 0; from < vertex_count; ++from) {
    t.neighbor_offsets[from + 1] += t.out_offsets[from + 1] - t.out_offsets[from];
    for (int i = t.out_offsets[from]; i < t.out_offsets[from + 1]; ++i)
      if (flags.no_way_back[at(i)]) ++t.neighbor_offsets[at(t.out_targets[at(i)]) + 1];
  }
  for (Index v = 0; v < vertex_count; ++v) t.neighbor_offsets[v + 1] += t.neighbor_offsets[v];
  t.neighbors.resize(at(t.neighbor_offsets.back()));
  std::vector<int> fill(t.neighbor_offsets.begin(), t.neighbor_offsets.end() - 1);
  for (Index from = 0; from < vertex_count; ++from)
    for (int i = t.out_offsets[from]; i < t.out_offsets[from + 1]; ++i) {
      const int to = t.out_targets[at(i)];
      t.neighbors[at(fill[from]++)] = to;
      if (flags.no_way_back[at(i)]) t.neighbors[at(fill[at(to)]++)] = static_cast<int>(from);
    }
  for (Index v = 0; v < vertex_count; ++v)
    std::sort(t.neighbors.begin() + t.neighbor_offsets[v], t.neighbors.begin() + t.neighbor_offsets[v + 1]);
  if (!flags.repeated_edges) return;
  // A vertex reached by two half-edges appears twice: drop repeats, compacting in place.
  int write = 0;
  for (Index v = 0; v < vertex_count; ++v) {
    const int row_start = write;
    for (int i = t.neighbor_offsets[v]; i < t.neighbor_offsets[v + 1]; ++i)
      if (write == row_start || t.neighbors[at(write - 1)] != t.neighbors[at(i)]) t.neighbors[at(write++)] = t.neighbors[at(i)];
    t.neighbor_offsets[v] = row_start;
  }
  t.neighbor_offsets[vertex_count] = write;
  t.neighbors.resize(at(write));
}

void walk_boundary_loops(const SlotFlags& flags, MeshTopology& t) {
  if (t.boundary_half_edges == 0) return;
  const int vertex_count = t.vertex_count();
  std::vector<char> used(t.out_half_edges.size(), 0);
  auto unused_boundary_slot_from = [&](int v) {
    for (int i = t.out_offsets[at(v)]; i < t.out_offsets[at(v) + 1]; ++i)
      if (flags.boundary[at(i)] && !used[at(i)]) return i;
    return -1;
  };
  for (int start = 0; start < vertex_count; ++start) {
    int leaving = 0;
    for (int i = t.out_offsets[at(start)]; i < t.out_offsets[at(start) + 1]; ++i) {
      if (!flags.boundary[at(i)]) continue;
      if (++leaving == 2 && t.first_pinch_vertex < 0) t.first_pinch_vertex = start;
      if (used[at(i)]) continue;
      std::vector<int> loop{start};
      bool closed = false;
      for (int slot = i; slot >= 0;) {
        used[at(slot)] = 1;
        const int to = t.out_targets[at(slot)];
        if (to == start) {
          closed = true;
          break;
        }
        loop.push_back(to);
        slot = unused_boundary_slot_from(to);
      }
      if (closed)
        t.boundary_loops.push_back(std::move(loop));
      else
        ++t.open_boundary_chains;
    }
  }
}

}  // namespace

int MeshTopology::find_half_edge(int from, int to) const {
  for (int i = out_offsets[at(from)]; i < out_offsets[at(from) + 1]; ++i)
    if (out_targets[at(i)] == to) return out_half_edges[at(i)];
  return -1;
}

MeshTopology build_mesh_topology(const Eigen::MatrixXi& F, Eigen::Index vertex_count, const std::vector<char>& ignored_faces) {
  MeshTopology topology;
  group_by_start_vertex(F, vertex_count, ignored_faces, topology);
  const SlotFlags flags = pair_half_edges(topology);
  collect_neighbours(flags, topology);
  walk_boundary_loops(flags, topology);
  return topology;
}

std::vector<int> face_components(const MeshTopology& topology, const std::vector<char>& in_set, int& component_count) {
  const int face_count = topology.face_count();
  auto member = [&in_set](int f) { return in_set.empty() || in_set[at(f)]; };
  std::vector<int> component(at(face_count), -1);
  std::vector<int> stack;
  component_count = 0;
  for (int seed = 0; seed < face_count; ++seed) {
    if (!member(seed) || component[at(seed)] >= 0) continue;
    component[at(seed)] = component_count;
    stack.push_back(seed);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int g = topology.face_across(3 * f + k);
        if (g < 0 || !member(g) || component[at(g)] >= 0) continue;
        component[at(g)] = component_count;
        stack.push_back(g);
      }
    }
    ++component_count;
  }
  return component;
}

std::vector<double> component_areas(const std::vector<int>& component, int component_count, const Eigen::VectorXd& areas) {
  std::vector<double> sums(at(component_count), 0.0);
  for (Index f = 0; f < component.size(); ++f)
    if (component[f] >= 0) sums[at(component[f])] += areas(static_cast<Eigen::Index>(f));
  return sums;
}

}  // namespace lastcut
