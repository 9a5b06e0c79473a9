#include "engine/style/forme_boundary.hpp"

#include <algorithm>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

struct EdgeEnds {
  EdgeKind kind;
  const char* from;
  const char* to;
};
constexpr std::array<EdgeEnds, 4> kEdgeEnds = {{{EdgeKind::Feather, "heel", "toe"},
                                                 {EdgeKind::FrontSeam, "toe", "top_front"},
                                                 {EdgeKind::BackSeam, "heel", "top_back"},
                                                 {EdgeKind::Top, "top_back", "top_front"}}};

// The loop's vertices from position `start` to the first landmark reached, walking by `step` (+1 or -1).
std::vector<int> walk(const std::vector<int>& loop, std::size_t start, int step, const std::vector<char>& is_landmark) {
  const std::size_t n = loop.size();
  std::vector<int> path{loop[start]};
  std::size_t at = start;
  do {
    at = step > 0 ? (at + 1) % n : (at + n - 1) % n;
    path.push_back(loop[at]);
  } while (!is_landmark[static_cast<std::size_t>(loop[at])] && at != start);
  return path;
}

}  // namespace

std::uint64_t FormeBoundary::edge_key(int u, int v) {
  const auto low = static_cast<std::uint64_t>(std::min(u, v)), high = static_cast<std::uint64_t>(std::max(u, v));
  return (high << 32) | low;
}

FormeBoundary forme_boundary(const TriMesh& mesh, const MeshTopology& topology, const std::map<std::string, int>& landmarks) {
  if (topology.boundary_loops.size() != 1)
    throw EngineError("a half of the upper must have one outline, this one has " +
                      std::to_string(topology.boundary_loops.size()));
  const std::vector<int>& loop = topology.boundary_loops.front();
  std::vector<char> is_landmark(static_cast<std::size_t>(mesh.V.rows()), 0);
  std::map<std::string, std::size_t> position;
  for (const char* name : kEdgeLandmarks) {
    const auto found = landmarks.find(name);
    if (found == landmarks.end()) throw EngineError(std::string("the half has no landmark ") + name);
    const auto at = std::find(loop.begin(), loop.end(), found->second);
    if (at == loop.end()) throw EngineError(std::string("the landmark ") + name + " is not on the half's outline");
    position[name] = static_cast<std::size_t>(at - loop.begin());
    is_landmark[static_cast<std::size_t>(found->second)] = 1;
  }
  FormeBoundary boundary;
  for (const EdgeEnds& ends : kEdgeEnds) {
    const int to_vertex = landmarks.at(ends.to);
    std::vector<int> path = walk(loop, position[ends.from], +1, is_landmark);
    if (path.back() != to_vertex) path = walk(loop, position[ends.from], -1, is_landmark);
    if (path.back() != to_vertex)
      throw EngineError(std::string("the half's landmarks are out of order: no outline edge runs from ") + ends.from +
                        " to " + ends.to);
    FormeEdge& edge = boundary.edges[static_cast<std::size_t>(ends.kind)];
    edge.kind = ends.kind;
    edge.vertices = std::move(path);
    edge.share.assign(edge.vertices.size(), 0.0);
    for (std::size_t i = 1; i < edge.vertices.size(); ++i)
      edge.share[i] = edge.share[i - 1] + (mesh.V.row(edge.vertices[i]) - mesh.V.row(edge.vertices[i - 1])).norm();
    const double length_mm = edge.share.back();
    if (!(length_mm > 0)) throw EngineError("an edge of the half's outline has no length");
    for (double& share : edge.share) share /= length_mm;
    for (std::size_t i = 1; i < edge.vertices.size(); ++i) {
      const int u = edge.vertices[i - 1], v = edge.vertices[i];
      boundary.spans[FormeBoundary::edge_key(u, v)] = {ends.kind, u, v, edge.share[i - 1], edge.share[i]};
    }
  }
  return boundary;
}

EdgeSpot spot_at_share(const FormeEdge& edge, double share) {
  share = std::clamp(share, 0.0, 1.0);
  const auto after = std::upper_bound(edge.share.begin() + 1, edge.share.end() - 1, share);
  const std::size_t i = static_cast<std::size_t>(after - edge.share.begin());  // 1 .. n-1
  const double span = edge.share[i] - edge.share[i - 1];
  const double weight_b = span > 0 ? std::clamp((share - edge.share[i - 1]) / span, 0.0, 1.0) : 0.0;
  return {edge.vertices[i - 1], edge.vertices[i], weight_b};
}

}  // namespace lastcut
