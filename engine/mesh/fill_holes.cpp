#include "engine/mesh/fill_holes.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/segment/half_edge_index.hpp"

namespace lastcut {
namespace {

// Boundary half-edges (from -> to, in the direction of the face that owns them: the ones without
// a twin), chained into loops. A vertex with two outgoing boundary edges (a pinch) is left to
// whichever loop reaches it first.
std::vector<std::vector<int>> boundary_loops_of(const Eigen::MatrixXi& F, Eigen::Index vertex_count) {
  const HalfEdgeIndex index = build_half_edge_index(F, vertex_count);
  std::vector<char> is_boundary(index.target.size(), 0), used(index.target.size(), 0);
  std::vector<int> boundary_edges;
  for (std::size_t from = 0; from + 1 < index.offsets.size(); ++from)
    for (int i = index.offsets[from]; i < index.offsets[from + 1]; ++i)
      if (index.find(index.target[static_cast<std::size_t>(i)], static_cast<int>(from)) < 0) {
        is_boundary[static_cast<std::size_t>(i)] = 1;
        boundary_edges.push_back(i);
      }
  auto unused_boundary_edge_from = [&](int vertex) {
    for (int i = index.offsets[static_cast<std::size_t>(vertex)]; i < index.offsets[static_cast<std::size_t>(vertex) + 1]; ++i)
      if (is_boundary[static_cast<std::size_t>(i)] && !used[static_cast<std::size_t>(i)]) return i;
    return -1;
  };
  auto start_of = [&](int edge) {
    return static_cast<int>(std::upper_bound(index.offsets.begin(), index.offsets.end(), edge) - index.offsets.begin()) - 1;
  };
  std::vector<std::vector<int>> loops;
  for (int start_edge : boundary_edges) {
    if (used[static_cast<std::size_t>(start_edge)]) continue;
    const int start = start_of(start_edge);
    std::vector<int> loop{start};
    bool closed = false;
    for (int edge = start_edge; edge >= 0;) {
      used[static_cast<std::size_t>(edge)] = 1;
      const int to = index.target[static_cast<std::size_t>(edge)];
      if (to == start) { closed = true; break; }
      loop.push_back(to);
      edge = unused_boundary_edge_from(to);
    }
    if (closed && loop.size() >= 3) loops.push_back(std::move(loop));
  }
  return loops;
}

double loop_diameter_mm(const Eigen::MatrixXd& V, const std::vector<int>& loop) {
  double largest_squared = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i)
    for (std::size_t j = i + 1; j < loop.size(); ++j)
      largest_squared = std::max(largest_squared, (V.row(loop[i]) - V.row(loop[j])).squaredNorm());
  return std::sqrt(largest_squared);
}

}  // namespace

int fill_holes(TriMesh& mesh, double max_diameter_mm) {
  const std::vector<std::vector<int>> loops = boundary_loops_of(mesh.F, mesh.V.rows());
  std::vector<Eigen::RowVector3d> new_vertices;
  std::vector<Eigen::RowVector3i> new_faces;
  int filled = 0;
  constexpr std::size_t kLargestLoopChecked = 4000;  // a loop this long is an opening, not a scan hole
  for (const std::vector<int>& loop : loops) {
    if (loop.size() > kLargestLoopChecked || loop_diameter_mm(mesh.V, loop) > max_diameter_mm) continue;
    ++filled;
    // The loop runs along the existing faces' edges, so the patch uses each edge reversed.
    if (loop.size() == 3) {
      new_faces.emplace_back(loop[2], loop[1], loop[0]);
      continue;
    }
    Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
    for (int v : loop) centroid += mesh.V.row(v);
    centroid /= static_cast<double>(loop.size());
    const int centre = static_cast<int>(mesh.V.rows() + static_cast<Eigen::Index>(new_vertices.size()));
    new_vertices.push_back(centroid);
    for (std::size_t i = 0; i < loop.size(); ++i)
      new_faces.emplace_back(loop[(i + 1) % loop.size()], loop[i], centre);
  }
  if (filled == 0) return 0;
  const Eigen::Index old_v = mesh.V.rows(), old_f = mesh.F.rows();
  mesh.V.conservativeResize(old_v + static_cast<Eigen::Index>(new_vertices.size()), 3);
  for (std::size_t i = 0; i < new_vertices.size(); ++i) mesh.V.row(old_v + static_cast<Eigen::Index>(i)) = new_vertices[i];
  mesh.F.conservativeResize(old_f + static_cast<Eigen::Index>(new_faces.size()), 3);
  for (std::size_t i = 0; i < new_faces.size(); ++i) mesh.F.row(old_f + static_cast<Eigen::Index>(i)) = new_faces[i];
  return filled;
}

}  // namespace lastcut
