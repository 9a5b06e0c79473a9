// Local untangling of flipped triangles by a regional Tutte embedding; see untangle.hpp.
#include "engine/flatten/untangle.hpp"

#include <Eigen/SparseCholesky>
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

// Re-places the movable vertices (movable_index[v] >= 0) by the uniform-weight Tutte embedding with every
// other vertex held. Returns false if the local system cannot be factored.
bool place_region(const DiskTopology& topology, const std::vector<int>& movable, const std::vector<int>& movable_index,
                  Eigen::MatrixXd& UV) {
  const int n = static_cast<int>(movable.size());
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 2);
  for (int i = 0; i < n; ++i) {
    const int v = movable[i];
    const int begin = topology.neighbor_offsets[v], end = topology.neighbor_offsets[v + 1];
    triplets.emplace_back(i, i, static_cast<double>(end - begin));
    for (int k = begin; k < end; ++k) {
      const int w = topology.neighbors[k];
      if (movable_index[w] >= 0) {
        triplets.emplace_back(i, movable_index[w], -1.0);
      } else {
        rhs.row(i) += UV.row(w);
      }
    }
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) return false;
  const Eigen::MatrixXd placed = solver.solve(rhs);
  for (int i = 0; i < n; ++i) UV.row(movable[i]) = placed.row(i);
  return true;
}

// Second strategy: Gauss-Seidel sweeps of the same averaging, growing one ring at a time, where mesh
// boundary vertices may slide to the middle of their two boundary neighbours (for folds that reach the outline).
UntangleReport relax_with_sliding_outline(const TriangleFrames& frames, const DiskTopology& topology,
                                          Eigen::MatrixXd& UV, const std::vector<int>& flipped, int max_rings) {
  UntangleReport report;
  report.flipped_before = report.flipped_after = static_cast<int>(flipped.size());
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
  const Eigen::MatrixXd original = UV;
  constexpr int kSweepsPerRing = 200;
  for (int ring = 1; ring <= max_rings; ++ring) {
    const size_t inner = region.size();
    for (size_t i = 0; i < inner; ++i) {
      for (int k = topology.neighbor_offsets[region[i]]; k < topology.neighbor_offsets[region[i] + 1]; ++k) {
        const int w = topology.neighbors[k];
        if (!in_region[w]) {
          in_region[w] = 1;
          region.push_back(w);
        }
      }
    }
    for (int sweep = 0; sweep < kSweepsPerRing; ++sweep) {
      for (size_t i = 0; i < inner; ++i) {
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
    report.moved_vertices = static_cast<int>(inner);
    report.flipped_after = static_cast<int>(flipped_triangles(frames, UV).size());
    if (report.flipped_after == 0) return report;
  }
  UV = original;
  report.flipped_after = report.flipped_before;
  return report;
}

UntangleReport regional_tutte(const TriangleFrames& frames, const DiskTopology& topology, Eigen::MatrixXd& UV,
                              const std::vector<int>& flipped, int max_rings) {
  UntangleReport report;
  report.flipped_before = static_cast<int>(flipped.size());
  report.flipped_after = report.flipped_before;

  const int vertex_count = static_cast<int>(UV.rows());
  std::vector<char> on_boundary(vertex_count, 0);
  for (int v : topology.boundary_loop) on_boundary[v] = 1;
  std::vector<char> in_region(vertex_count, 0);
  std::vector<int> region;  // breadth-first order: ring by ring
  for (int f : flipped) {
    for (int v : frames.triangles[f]) {
      if (!in_region[v]) {
        in_region[v] = 1;
        region.push_back(v);
      }
    }
  }
  const Eigen::MatrixXd original = UV;
  int rings = 0;
  size_t ring_start = 0;
  for (int target = 2; target <= max_rings; target *= 2) {
    // Grow to `target` rings; the last ring added is held, everything inside it moves.
    size_t inner_end = region.size();
    for (; rings < target; ++rings) {
      inner_end = region.size();
      for (size_t i = ring_start; i < inner_end; ++i) {
        const int v = region[i];
        for (int k = topology.neighbor_offsets[v]; k < topology.neighbor_offsets[v + 1]; ++k) {
          const int w = topology.neighbors[k];
          if (!in_region[w]) {
            in_region[w] = 1;
            region.push_back(w);
          }
        }
      }
      ring_start = inner_end;
    }
    std::vector<int> movable;
    std::vector<int> movable_index(vertex_count, -1);
    for (size_t i = 0; i < inner_end; ++i) {
      const int v = region[i];
      if (on_boundary[v]) continue;
      movable_index[v] = static_cast<int>(movable.size());
      movable.push_back(v);
    }
    UV = original;
    if (movable.empty() || !place_region(topology, movable, movable_index, UV)) continue;
    report.rings = rings;
    report.moved_vertices = static_cast<int>(movable.size());
    report.flipped_after = static_cast<int>(flipped_triangles(frames, UV).size());
    if (report.flipped_after == 0) return report;
  }
  UV = original;
  report.flipped_after = report.flipped_before;
  return report;
}

}  // namespace

UntangleReport untangle_flips(const TriangleFrames& frames, const DiskTopology& topology, Eigen::MatrixXd& UV,
                              int max_rings) {
  const std::vector<int> flipped = flipped_triangles(frames, UV);
  if (flipped.empty()) return {};
  const UntangleReport exact = regional_tutte(frames, topology, UV, flipped, max_rings);
  if (exact.flipped_after == 0) return exact;
  return relax_with_sliding_outline(frames, topology, UV, flipped, max_rings / 2);
}

}  // namespace lastcut
