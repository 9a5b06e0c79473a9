// Local untangling of flipped triangles: star kernels, then regional embeddings; see untangle.hpp.
#include "engine/flatten/untangle.hpp"

#include "engine/flatten/star_untangle.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <utility>
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

// Smallest half-edge weight of the shape-preserving placement (cot(89.4 deg) / 2): clamping the
// cotangent weights keeps every weight positive, so each vertex lands inside the hull of its neighbours.
constexpr double kMinimumHalfWeight = 0.01;
// Star untangling after a regional placement: a few rings and sweeps around what is left folded.
constexpr int kCleanupRings = 4;
constexpr int kCleanupSweeps = 64;

// Re-places the movable vertices (movable_index[v] >= 0) by a convex-combination embedding with every other
// vertex held. Uniform weights (cotangent_weighted false) are Tutte's; clamped cotangent weights from the
// 3D triangles reproduce a flat region exactly and a curved one nearly isometrically, so the region keeps
// the shape ARAP gave its held ring and does not bunch up against a concave stretch of it.
// Returns false if the local system cannot be factored.
bool place_region(const TriangleFrames& frames, const std::vector<int>& movable,
                  const std::vector<int>& movable_index, bool cotangent_weighted, Eigen::MatrixXd& UV) {
  const int n = static_cast<int>(movable.size());
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 2);
  // Summed over the triangles: an interior edge gets both halves of its weight (uniform: 1 + 1).
  for (size_t f = 0; f < frames.triangles.size(); ++f) {
    const auto& t = frames.triangles[f];
    if (movable_index[t[0]] < 0 && movable_index[t[1]] < 0 && movable_index[t[2]] < 0) continue;
    for (int k = 0; k < 3; ++k) {
      const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      const double w = cotangent_weighted ? std::max(frames.half_weight[3 * f + k], kMinimumHalfWeight) : 1.0;
      for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
        const int row = movable_index[from];
        if (row < 0) continue;
        triplets.emplace_back(row, row, w);
        if (movable_index[to] >= 0) {
          triplets.emplace_back(row, movable_index[to], -w);
        } else {
          rhs.row(row) += w * UV.row(to);
        }
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

// 1 for the vertices of the outline (the disk's boundary loop), #V.
std::vector<char> outline_flags(const MeshTopology& topology, int vertex_count) {
  std::vector<char> on_boundary(static_cast<size_t>(vertex_count), 0);
  for (int v : topology.boundary_loops[0]) on_boundary[v] = 1;
  return on_boundary;
}

// The corners of the flipped triangles, each once in order of first appearance, marked in in_region (#V).
std::vector<int> corners_of(const TriangleFrames& frames, const std::vector<int>& flipped, std::vector<char>& in_region) {
  std::vector<int> region;
  for (int f : flipped) {
    for (int v : frames.triangles[f]) {
      if (!in_region[v]) {
        in_region[v] = 1;
        region.push_back(v);
      }
    }
  }
  return region;
}

// Second strategy: Gauss-Seidel sweeps of the same averaging, growing one ring at a time, where mesh
// boundary vertices may slide to the middle of their two boundary neighbours (for folds that reach the outline).
UntangleReport relax_with_sliding_outline(const TriangleFrames& frames, const MeshTopology& topology,
                                          Eigen::MatrixXd& UV, const std::vector<int>& flipped, int max_rings) {
  UntangleReport report;
  report.flipped_before = report.flipped_after = static_cast<int>(flipped.size());
  const std::vector<char> on_boundary = outline_flags(topology, static_cast<int>(UV.rows()));
  std::vector<char> in_region(static_cast<size_t>(UV.rows()), 0);
  std::vector<int> region = corners_of(frames, flipped, in_region);
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

UntangleReport regional_tutte(const TriangleFrames& frames, const MeshTopology& topology, Eigen::MatrixXd& UV,
                              const std::vector<int>& flipped, int max_rings) {
  UntangleReport report;
  report.flipped_before = static_cast<int>(flipped.size());
  report.flipped_after = report.flipped_before;

  const std::vector<char> on_boundary = outline_flags(topology, static_cast<int>(UV.rows()));
  std::vector<char> in_region(static_cast<size_t>(UV.rows()), 0);
  std::vector<int> region = corners_of(frames, flipped, in_region);  // then grown breadth-first: ring by ring
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
    std::vector<int> movable_index(static_cast<size_t>(UV.rows()), -1);
    for (size_t i = 0; i < inner_end; ++i) {
      const int v = region[i];
      if (on_boundary[v]) continue;
      movable_index[v] = static_cast<int>(movable.size());
      movable.push_back(v);
    }
    if (movable.empty()) continue;
    for (const bool cotangent_weighted : {true, false}) {
      UV = original;
      if (!place_region(frames, movable, movable_index, cotangent_weighted, UV)) continue;
      report.rings = rings;
      report.moved_vertices = static_cast<int>(movable.size());
      report.flipped_after = static_cast<int>(flipped_triangles(frames, UV).size());
      // What a concave stretch of the held ring leaves folded next to it is a few slivers: star untangling
      // removes those.
      if (report.flipped_after > 0) {
        report.flipped_after = star_untangle(frames, topology, UV, kCleanupRings, kCleanupSweeps).flipped_after;
      }
      if (report.flipped_after == 0) return report;
    }
  }
  UV = original;
  report.flipped_after = report.flipped_before;
  return report;
}

}  // namespace

UntangleReport untangle_flips(const TriangleFrames& frames, const MeshTopology& topology, Eigen::MatrixXd& UV,
                              int max_rings) {
  const std::vector<int> flipped = flipped_triangles(frames, UV);
  if (flipped.empty()) return {};
  const StarUntangleReport star = star_untangle(frames, topology, UV);
  if (star.flipped_after == 0) {
    return {star.flipped_before, 0, star.rings, star.moved_vertices};
  }
  const UntangleReport exact = regional_tutte(frames, topology, UV, flipped, max_rings);
  if (exact.flipped_after == 0) return exact;
  return relax_with_sliding_outline(frames, topology, UV, flipped, max_rings / 2);
}

}  // namespace lastcut
