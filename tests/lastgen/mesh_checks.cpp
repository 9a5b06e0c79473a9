#include "mesh_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace lastcut::test {

EdgeCensus edge_census(const TriMesh& mesh) {
  // For each undirected edge: how many faces use it in each direction.
  std::map<std::pair<int, int>, std::pair<int, int>> uses;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int a = mesh.F(f, c), b = mesh.F(f, (c + 1) % 3);
      auto& entry = uses[{std::min(a, b), std::max(a, b)}];
      (a < b ? entry.first : entry.second) += 1;
    }
  EdgeCensus census;
  std::map<int, std::vector<int>> boundary_neighbours;
  for (const auto& [edge, count] : uses) {
    const int total = count.first + count.second;
    if (total == 1) {
      ++census.boundary_edges;
      boundary_neighbours[edge.first].push_back(edge.second);
      boundary_neighbours[edge.second].push_back(edge.first);
    } else if (total > 2) {
      ++census.non_manifold_edges;
    } else if (count.first != 1) {
      ++census.inconsistent_edges;
    }
  }
  std::set<int> seen;
  for (const auto& [start, unused] : boundary_neighbours) {
    if (seen.count(start)) continue;
    ++census.boundary_loops;
    census.loop_vertices.emplace_back();
    std::vector<int> stack{start};
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      if (!seen.insert(v).second) continue;
      census.loop_vertices.back().push_back(v);
      for (const int w : boundary_neighbours[v]) stack.push_back(w);
    }
  }
  return census;
}

double signed_volume_mm3(const TriMesh& mesh) {
  double volume = 0.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

int euler_characteristic(const TriMesh& mesh) {
  std::set<std::pair<int, int>> edges;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int a = mesh.F(f, c), b = mesh.F(f, (c + 1) % 3);
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  return static_cast<int>(mesh.V.rows()) - static_cast<int>(edges.size()) + static_cast<int>(mesh.F.rows());
}

double worst_triangle_quality(const TriMesh& mesh) {
  double worst = 1.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const double area = 0.5 * (b - a).cross(c - a).norm();
    const double squares = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
    worst = std::min(worst, 4.0 * std::sqrt(3.0) * area / squares);
  }
  return worst;
}

}  // namespace lastcut::test
