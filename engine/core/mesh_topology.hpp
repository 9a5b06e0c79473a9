#pragma once
// Connectivity of a triangle mesh, built once per mesh and shared by repair, segmentation,
// flattening and molds.
//
// Half-edge h = 3 f + k runs from F(f,k) to F(f,(k+1)%3). The half-edges are grouped by their
// start vertex (compressed rows), so the other half-edge of an edge a-b is found among the few
// half-edges leaving a or b: linear time and memory, no hashing and no global sort (scans have
// 400k triangles). The mesh may be a soup (repair): an edge may be used by one face (boundary),
// two faces running it either way, or more (crowded, non-manifold).
//
// Inputs:  F #F x 3 vertex indices in [0, vertex_count); faces flagged in `ignored_faces`
//          (#F, or empty: none) are left out, as if deleted.
// Outputs: per half-edge (3 #F): the other half-edge on its edge and whether it runs the same way;
//          per vertex: its half-edges and sorted neighbours; the oriented boundary loops.
// No coordinates are read: the topology holds for any V with vertex_count rows.
#include <Eigen/Core>
#include <vector>

namespace lastcut {

// Values of MeshTopology::across besides a half-edge index.
constexpr int kBoundaryEdge = -1;  // no other face uses the edge
constexpr int kCrowdedEdge = -2;   // two or more other faces use the edge (non-manifold)

struct MeshTopology {
  // Half-edges leaving vertex v: out_half_edges[out_offsets[v] .. out_offsets[v+1]), increasing h.
  std::vector<int> out_offsets;     // #V + 1
  std::vector<int> out_half_edges;  // one entry per half-edge of a kept face
  std::vector<int> out_targets;     // end vertex of out_half_edges[i]
  // Per half-edge h (3 #F): the one other half-edge on h's edge, kBoundaryEdge or kCrowdedEdge
  // (also kBoundaryEdge for the half-edges of ignored faces).
  std::vector<int> across;
  // Per half-edge: across[h] runs the edge the same way as h (neighbouring faces disagree on
  // their orientation). 0 when across[h] is a marker.
  std::vector<char> same_direction;
  // Vertices sharing an edge with v: neighbors[neighbor_offsets[v] .. neighbor_offsets[v+1]), sorted, no repeats.
  std::vector<int> neighbor_offsets;  // #V + 1
  std::vector<int> neighbors;
  // Closed chains of boundary half-edges, each in the direction of its faces (interior on the left
  // for counter-clockwise faces), starting at its lowest vertex, in order of that vertex. Where two
  // boundary half-edges leave one vertex (a pinch) the walk takes the first one not yet used.
  std::vector<std::vector<int>> boundary_loops;
  int first_pinch_vertex = -1;    // lowest vertex with two outgoing boundary half-edges, or -1
  int open_boundary_chains = 0;   // boundary walks that did not come back (inconsistent orientation)
  long long boundary_half_edges = 0;

  int vertex_count() const { return static_cast<int>(out_offsets.size()) - 1; }
  int face_count() const { return static_cast<int>(across.size() / 3); }
  // Half-edge from -> to (the lowest h if several), or -1.
  int find_half_edge(int from, int to) const;
  // The face across half-edge h, or kBoundaryEdge / kCrowdedEdge.
  int face_across(int h) const {
    const int other = across[static_cast<std::size_t>(h)];
    return other < 0 ? other : other / 3;
  }
  // The face across edge F(f,k) -> F(f,(k+1)%3).
  int face_across(Eigen::Index f, int k) const { return face_across(static_cast<int>(3 * f + k)); }
  // The half-edge running h's edge the other way in the one neighbouring face, or -1.
  int twin(int h) const {
    const auto i = static_cast<std::size_t>(h);
    return across[i] >= 0 && !same_direction[i] ? across[i] : -1;
  }
  // Undirected edges: (half-edges + boundary half-edges) / 2 on an edge-manifold mesh.
  long long edge_count() const {
    return (static_cast<long long>(out_half_edges.size()) + boundary_half_edges) / 2;
  }
};

// Throws EngineError when a face refers to a vertex outside [0, vertex_count).
MeshTopology build_mesh_topology(const Eigen::MatrixXi& F, Eigen::Index vertex_count,
                                 const std::vector<char>& ignored_faces = {});

// Connected components (across edges with exactly two faces) of the faces with in_set[f] != 0
// (in_set #F, or empty: all faces). Returns #F component ids, -1 outside the set, numbered in
// order of their lowest face; component_count receives their number.
std::vector<int> face_components(const MeshTopology& topology, const std::vector<char>& in_set, int& component_count);

// Sum of areas (mm^2) per component id; component #F ids as above, areas #F (mm^2).
std::vector<double> component_areas(const std::vector<int>& component, int component_count, const Eigen::VectorXd& areas);

}  // namespace lastcut
