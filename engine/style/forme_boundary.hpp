#pragma once
// The outline of one half of an upper, split at its four landmarks into the edges a style refers to and
// parameterised by the share of each edge's 3D length: a point of the reference last's feather line
// 40 % of the way from heel to toe corresponds to the point 40 % of the way along the new last's.
// Measuring on the 3D surface (not the flattening) makes the centre seams, which both halves share,
// correspond identically from either side.
//   Feather    heel -> toe         (the feather line, where the upper meets the insole)
//   BackSeam   heel -> top_back    (the back centre cut)
//   Top        top_back -> top_front (the top edge)
//   FrontSeam  toe -> top_front    (the front centre cut)
#include <Eigen/Core>
#include <array>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"
#include "engine/mold/edge_allowance.hpp"

namespace lastcut {

struct FormeEdge {
  EdgeKind kind = EdgeKind::Feather;
  std::vector<int> vertices;  // from the edge's first landmark to its second, >= 2
  std::vector<double> share;  // per vertex: 3D arc length from the first landmark / the edge's length, 0 .. 1
};

// Where a share of an edge lies: between vertices a and b, weight_b of the way.
struct EdgeSpot {
  int a = -1, b = -1;
  double weight_b = 0;
};

struct FormeBoundary {
  std::array<FormeEdge, 4> edges;  // indexed by static_cast<int>(EdgeKind)
  // Every boundary edge of the mesh (key: edge_key(u, v)): which forme edge it lies on and the shares of u and v.
  struct Span {
    EdgeKind kind;
    int u, v;
    double share_u, share_v;
  };
  std::unordered_map<std::uint64_t, Span> spans;

  const FormeEdge& edge(EdgeKind kind) const { return edges[static_cast<std::size_t>(kind)]; }
  static std::uint64_t edge_key(int u, int v);
};

// mesh: a half (#V x 3, mm); topology: its, one boundary loop; landmarks: "toe", "heel", "top_back",
// "top_front" on that loop. Throws EngineError (one line) when the half has no single loop or a landmark
// is missing or off the loop, or when the landmarks do not run toe, heel, top_back, top_front around it.
FormeBoundary forme_boundary(const TriMesh& mesh, const MeshTopology& topology, const std::map<std::string, int>& landmarks);

// The spot at `share` (clamped to 0 .. 1) of the edge.
EdgeSpot spot_at_share(const FormeEdge& edge, double share);

}  // namespace lastcut
