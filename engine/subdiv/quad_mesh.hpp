#pragma once
// QuadMesh: a quad control mesh (libigl layout) and its connectivity, for the Bezier surface of
// engine/subdiv.
//   V  #V x 3 double, vertex positions in millimetres
//   Q  #Q x 4 int, vertex indices, counter-clockwise seen from outside
// Half-edge h = 4 q + k runs from Q(q,k) to Q(q,(k+1)%4).
#include <Eigen/Core>
#include <vector>

namespace lastcut {

struct QuadMesh {
  Eigen::MatrixXd V;  // #V x 3, mm
  Eigen::MatrixXi Q;  // #Q x 4

  int vertex_count() const { return static_cast<int>(V.rows()); }
  int quad_count() const { return static_cast<int>(Q.rows()); }
};

// The connectivity the patch construction needs. The mesh must be an oriented 2-manifold, possibly
// with boundary: every edge used once or twice (run opposite ways), every vertex one fan of faces.
struct QuadTopology {
  std::vector<int> twin;  // 4 #Q: the half-edge running h's edge the other way, -1 on the boundary
  // The fan of vertex v: outgoing half-edges ring[ring_offsets[v] .. ring_offsets[v+1]), one per
  // incident face, counter-clockwise around v seen from outside. A boundary vertex's fan starts at
  // its outgoing boundary half-edge. Vertices used by no face have an empty fan.
  std::vector<int> ring_offsets;  // #V + 1
  std::vector<int> ring;
  std::vector<int> ring_position;  // 4 #Q: position of h in its start vertex's fan
  std::vector<char> on_boundary;   // #V
  std::vector<int> edge_of;        // 4 #Q: undirected edge id of h
  std::vector<int> edge_half_edge; // #E: the half-edge that represents the edge (lower of the two)
  int edge_count() const { return static_cast<int>(edge_half_edge.size()); }

  int faces_at(int v) const { return ring_offsets[static_cast<size_t>(v) + 1] - ring_offsets[static_cast<size_t>(v)]; }
  // Number of edges at v: faces + 1 on the boundary.
  int valence(int v) const { return faces_at(v) + (on_boundary[static_cast<size_t>(v)] ? 1 : 0); }
  int half_edge_at(int v, int j) const { return ring[static_cast<size_t>(ring_offsets[static_cast<size_t>(v)] + j)]; }
};

inline int next_half_edge(int h) { return (h & ~3) | ((h + 1) & 3); }
inline int prev_half_edge(int h) { return (h & ~3) | ((h + 3) & 3); }

// Throws EngineError (one line) for indices out of range, a quad with a repeated corner, an edge
// used by more than two faces or twice the same way, or a vertex whose faces form several fans.
QuadTopology build_quad_topology(const QuadMesh& mesh);

}  // namespace lastcut
