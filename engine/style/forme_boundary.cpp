#include "engine/style/forme_boundary.hpp"

#include <algorithm>
#include <cmath>

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

// The share of each vertex along a boundary polyline, measured on the curve with its triangle-scale
// zigzag smoothed away: a level-set cut crosses each triangle on a chord, and the chords of a coarse and a
// fine mesh add up to different lengths in different places, which would slide the correspondence along
// the edge by most of a millimetre. The polyline is resampled every kSampleStep_mm of its own length,
// smoothed by binomial passes (a Gaussian of about kSmoothingSigma_mm, ends fixed) and measured again.
std::vector<double> smoothed_shares(const TriMesh& mesh, const std::vector<int>& vertices) {
  constexpr double kSampleStep_mm = 0.5, kSmoothingSigma_mm = 3.0;
  std::vector<double> raw(vertices.size(), 0.0);
  for (std::size_t i = 1; i < vertices.size(); ++i)
    raw[i] = raw[i - 1] + (mesh.V.row(vertices[i]) - mesh.V.row(vertices[i - 1])).norm();
  const double length_mm = raw.back();
  if (!(length_mm > 0)) throw EngineError("an edge of the half's outline has no length");
  const int steps = std::max(2, static_cast<int>(std::ceil(length_mm / kSampleStep_mm)));
  std::vector<Eigen::Vector3d> samples(static_cast<std::size_t>(steps) + 1);
  std::size_t segment = 1;
  for (int j = 0; j <= steps; ++j) {
    const double at = length_mm * j / steps;
    while (segment + 1 < raw.size() && raw[segment] < at) ++segment;
    const double span = raw[segment] - raw[segment - 1];
    const double t = span > 0 ? std::clamp((at - raw[segment - 1]) / span, 0.0, 1.0) : 0.0;
    samples[static_cast<std::size_t>(j)] =
        (1 - t) * mesh.V.row(vertices[segment - 1]).transpose() + t * mesh.V.row(vertices[segment]).transpose();
  }
  // A binomial pass (1/4, 1/2, 1/4) adds variance step^2 / 2.
  const int passes = static_cast<int>(std::ceil(2 * std::pow(kSmoothingSigma_mm / (length_mm / steps), 2)));
  std::vector<Eigen::Vector3d> next = samples;
  for (int pass = 0; pass < passes; ++pass) {
    for (std::size_t j = 1; j + 1 < samples.size(); ++j) next[j] = 0.25 * samples[j - 1] + 0.5 * samples[j] + 0.25 * samples[j + 1];
    std::swap(samples, next);
  }
  std::vector<double> smooth(samples.size(), 0.0);
  for (std::size_t j = 1; j < samples.size(); ++j) smooth[j] = smooth[j - 1] + (samples[j] - samples[j - 1]).norm();
  std::vector<double> share(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const double position = raw[i] / length_mm * steps;
    const std::size_t j = std::min(static_cast<std::size_t>(position), static_cast<std::size_t>(steps) - 1);
    const double t = position - static_cast<double>(j);
    share[i] = ((1 - t) * smooth[j] + t * smooth[j + 1]) / smooth.back();
  }
  share.front() = 0;
  share.back() = 1;
  return share;
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
    edge.share = smoothed_shares(mesh, edge.vertices);
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
