#include "engine/mesh/fill_holes.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/mesh_topology.hpp"

namespace lastcut {
namespace {

double loop_diameter_mm(const Eigen::MatrixXd& V, const std::vector<int>& loop) {
  double largest_squared = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i)
    for (std::size_t j = i + 1; j < loop.size(); ++j)
      largest_squared = std::max(largest_squared, (V.row(loop[i]) - V.row(loop[j])).squaredNorm());
  return std::sqrt(largest_squared);
}

}  // namespace

int fill_holes(TriMesh& mesh, double max_diameter_mm) {
  // The loops run along the faces' own edges; at a pinch a loop takes whichever boundary edge comes first.
  const std::vector<std::vector<int>> loops = build_mesh_topology(mesh.F, mesh.V.rows()).boundary_loops;
  std::vector<Eigen::RowVector3d> new_vertices;
  std::vector<Eigen::RowVector3i> new_faces;
  int filled = 0;
  constexpr std::size_t kLargestLoopChecked = 4000;  // a loop this long is an opening, not a scan hole
  for (const std::vector<int>& loop : loops) {
    if (loop.size() < 3 || loop.size() > kLargestLoopChecked || loop_diameter_mm(mesh.V, loop) > max_diameter_mm) continue;
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
