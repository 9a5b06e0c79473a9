// Local untangling of flipped triangles by regional uniform-Laplacian relaxation; see untangle.hpp.
#include "engine/flatten/untangle.hpp"

#include <vector>

namespace lastcut {
namespace {

std::vector<int> flipped_triangles(const TriangleFrames& frames, const Eigen::MatrixXd& UV) {
  std::vector<int> flipped;
  for (size_t f = 0; f < frames.triangles.size(); ++f) {
    const auto& t = frames.triangles[f];
    const Eigen::Vector2d a = UV.row(t[1]) - UV.row(t[0]);
    const Eigen::Vector2d b = UV.row(t[2]) - UV.row(t[0]);
    if (a.x() * b.y() - a.y() * b.x() <= 0.0) flipped.push_back(static_cast<int>(f));
  }
  return flipped;
}

}  // namespace

UntangleReport untangle_flips(const TriangleFrames& frames, const DiskTopology& topology, Eigen::MatrixXd& UV,
                              int max_rings) {
  UntangleReport report;
  std::vector<int> flipped = flipped_triangles(frames, UV);
  report.flipped_before = static_cast<int>(flipped.size());
  report.flipped_after = report.flipped_before;
  if (flipped.empty()) return report;

  const int vertex_count = static_cast<int>(UV.rows());
  std::vector<char> on_boundary(vertex_count, 0);
  for (int v : topology.boundary_loop) on_boundary[v] = 1;
  std::vector<char> in_region(vertex_count, 0);
  std::vector<int> region;
  for (int f : flipped) {
    for (int v : frames.triangles[f]) {
      if (!in_region[v]) {
        in_region[v] = 1;
        region.push_back(v);
      }
    }
  }
  constexpr int kSweepsPerRing = 60;
  for (int ring = 1; ring <= max_rings; ++ring) {
    const size_t previous = region.size();
    for (size_t i = 0; i < previous; ++i) {
      const int v = region[i];
      for (int k = topology.neighbor_offsets[v]; k < topology.neighbor_offsets[v + 1]; ++k) {
        const int w = topology.neighbors[k];
        if (!in_region[w]) {
          in_region[w] = 1;
          region.push_back(w);
        }
      }
    }
    // The region's outermost ring stays put; inner vertices relax. Boundary vertices of the mesh relax
    // along their two boundary neighbours only, so the outline stays an outline.
    std::vector<char> movable(region.size(), 0);
    for (size_t i = 0; i < previous; ++i) movable[i] = 1;
    for (int sweep = 0; sweep < kSweepsPerRing; ++sweep) {
      for (size_t i = 0; i < previous; ++i) {
        const int v = region[i];
        Eigen::RowVector2d sum(0.0, 0.0);
        int count = 0;
        for (int k = topology.neighbor_offsets[v]; k < topology.neighbor_offsets[v + 1]; ++k) {
          const int w = topology.neighbors[k];
          if (on_boundary[v] && !on_boundary[w]) continue;
          sum += UV.row(w);
          ++count;
        }
        if (count > 0) UV.row(v) = sum / count;
      }
    }
    report.rings = ring;
    report.moved_vertices = static_cast<int>(previous);
    report.flipped_after = static_cast<int>(flipped_triangles(frames, UV).size());
    if (report.flipped_after == 0) break;
  }
  return report;
}

}  // namespace lastcut
