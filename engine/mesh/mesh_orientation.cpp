#include "engine/mesh/mesh_orientation.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <string>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/mesh/mesh_edges.hpp"

namespace lastcut {

using mesh_detail::face_adjacency;
using mesh_detail::FaceAdjacency;
using mesh_detail::UnionFind;

namespace {

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f%%", 100.0 * fraction);
  return text;
}

}  // namespace

double signed_volume_mm3(const TriMesh& mesh) {
  double volume = 0.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    volume += a.dot(b.cross(c));
  }
  return volume / 6.0;
}

void keep_largest_component(TriMesh& mesh, double debris_fraction, IntakeReport& report) {
  UnionFind pieces(static_cast<size_t>(mesh.F.rows()));
  const FaceAdjacency adjacency = face_adjacency(mesh, {});
  for (size_t corner = 0; corner < adjacency.neighbour.size(); ++corner)
    if (adjacency.neighbour[corner] >= 0) pieces.unite(static_cast<int>(corner / 3), adjacency.neighbour[corner]);
  const Eigen::VectorXd areas = triangle_areas(mesh);
  std::vector<double> piece_area(static_cast<size_t>(mesh.F.rows()), 0.0);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) piece_area[static_cast<size_t>(pieces.find(static_cast<int>(f)))] += areas(f);
  std::vector<std::pair<double, int>> ranked;
  for (size_t root = 0; root < piece_area.size(); ++root)
    if (pieces.find(static_cast<int>(root)) == static_cast<int>(root)) ranked.emplace_back(piece_area[root], static_cast<int>(root));
  std::sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
  if (ranked.size() <= 1) return;
  const double largest = ranked[0].first;
  const double second_fraction = largest > 0.0 ? ranked[1].first / largest : 1.0;
  if (second_fraction > 0.10)
    throw EngineError("several disconnected pieces (" + std::to_string(ranked.size()) + " pieces, the second has " +
                      percent(second_fraction) + " of the largest's area)");
  int debris = 0;
  for (size_t k = 1; k < ranked.size(); ++k) {
    if (ranked[k].first >= debris_fraction * largest)
      report.notes.push_back("removed a separate piece with " + percent(ranked[k].first / largest) + " of the main area");
    else
      ++debris;
  }
  if (debris > 0) report.notes.push_back("removed " + std::to_string(debris) + " specks of scanner debris");
  report.loose_components_removed += static_cast<int>(ranked.size()) - 1;
  std::vector<char> removed(static_cast<size_t>(mesh.F.rows()), 0);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) removed[static_cast<size_t>(f)] = pieces.find(static_cast<int>(f)) != ranked[0].second;
  mesh_detail::drop_faces(mesh, removed);
  mesh_detail::drop_unreferenced_vertices(mesh);
}

int orient_outward(TriMesh& mesh, IntakeReport& report) {
  const FaceAdjacency adjacency = face_adjacency(mesh, {});
  std::vector<signed char> flip(static_cast<size_t>(mesh.F.rows()), -1);  // -1 not yet visited
  bool orientable = true;
  for (Eigen::Index seed = 0; seed < mesh.F.rows(); ++seed) {
    if (flip[static_cast<size_t>(seed)] >= 0) continue;
    // Breadth-first from the seed, keeping the seed as it is: each neighbour must run the shared
    // edge the other way round.
    flip[static_cast<size_t>(seed)] = 0;
    std::deque<int> queue{static_cast<int>(seed)};
    while (!queue.empty()) {
      const int face = queue.front();
      queue.pop_front();
      for (int c = 0; c < 3; ++c) {
        const size_t corner = 3 * static_cast<size_t>(face) + static_cast<size_t>(c);
        const int next = adjacency.neighbour[corner];
        if (next < 0) continue;
        const signed char wanted = static_cast<signed char>(flip[static_cast<size_t>(face)] ^ adjacency.same_direction[corner]);
        if (flip[static_cast<size_t>(next)] < 0) {
          flip[static_cast<size_t>(next)] = wanted;
          queue.push_back(next);
        } else if (flip[static_cast<size_t>(next)] != wanted) {
          orientable = false;
        }
      }
    }
  }
  if (!orientable) report.notes.push_back("the surface is not orientable (Moebius-like); orientation is approximate");
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    if (flip[static_cast<size_t>(f)] == 1) mesh.F.row(f) = Eigen::RowVector3i(mesh.F(f, 0), mesh.F(f, 2), mesh.F(f, 1));
  int flipped = static_cast<int>(std::count(flip.begin(), flip.end(), 1));
  if (signed_volume_mm3(mesh) < 0.0) {
    mesh.F.col(1).swap(mesh.F.col(2));
    flipped = static_cast<int>(mesh.F.rows()) - flipped;
  }
  return flipped;
}

int count_boundary_loops(const TriMesh& mesh) {
  const FaceAdjacency adjacency = face_adjacency(mesh, {});
  UnionFind chains(static_cast<size_t>(mesh.V.rows()));
  std::vector<char> on_boundary(static_cast<size_t>(mesh.V.rows()), 0);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) {
      if (adjacency.neighbour[static_cast<size_t>(3 * f + c)] != mesh_detail::kBoundaryEdge) continue;
      const int a = mesh.F(f, c), b = mesh.F(f, (c + 1) % 3);
      chains.unite(a, b);
      on_boundary[static_cast<size_t>(a)] = on_boundary[static_cast<size_t>(b)] = 1;
    }
  int loops = 0;
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    if (on_boundary[static_cast<size_t>(v)] && chains.find(static_cast<int>(v)) == static_cast<int>(v)) ++loops;
  return loops;
}

}  // namespace lastcut
