#include "engine/mesh/fill_holes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace lastcut {
namespace {

std::uint64_t edge_key(int from, int to) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(from)) << 32) | static_cast<std::uint32_t>(to);
}

// Boundary half-edges (from -> to, in the direction of the face that owns them), chained into
// loops. A vertex with two outgoing boundary edges (a pinch) is left to whichever loop reaches it first.
std::vector<std::vector<int>> boundary_loops_of(const Eigen::MatrixXi& F) {
  std::unordered_map<std::uint64_t, int> half_edges;
  half_edges.reserve(static_cast<std::size_t>(F.rows()) * 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) half_edges.emplace(edge_key(F(f, k), F(f, (k + 1) % 3)), 0);
  std::unordered_multimap<int, int> next;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int from = F(f, k), to = F(f, (k + 1) % 3);
      if (!half_edges.contains(edge_key(to, from))) next.emplace(from, to);
    }
  std::vector<int> starts;
  for (const auto& [from, to] : next) starts.push_back(from);
  std::sort(starts.begin(), starts.end());  // deterministic order whatever the hash layout
  std::unordered_map<std::uint64_t, bool> used;
  std::vector<std::vector<int>> loops;
  for (int start : starts) {
    std::vector<int> loop{start};
    int current = start;
    bool closed = false;
    while (true) {
      int chosen = -1;
      auto range = next.equal_range(current);
      for (auto it = range.first; it != range.second; ++it)
        if (!used[edge_key(current, it->second)] && (chosen < 0 || it->second < chosen)) chosen = it->second;
      if (chosen < 0) break;
      used[edge_key(current, chosen)] = true;
      if (chosen == start) { closed = true; break; }
      loop.push_back(chosen);
      current = chosen;
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
  const std::vector<std::vector<int>> loops = boundary_loops_of(mesh.F);
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
