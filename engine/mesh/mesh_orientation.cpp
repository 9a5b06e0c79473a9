#include "engine/mesh/mesh_orientation.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <string>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/core/mesh_topology.hpp"
#include "engine/mesh/mesh_face_edits.hpp"

namespace lastcut {

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

void keep_largest_component(TriMesh& mesh, MeshTopology& topology, double debris_fraction, IntakeReport& report) {
  int piece_count = 0;
  const std::vector<int> piece = face_components(topology, {}, piece_count);
  const std::vector<double> piece_area = component_areas(piece, piece_count, triangle_areas(mesh));
  std::vector<std::pair<double, int>> ranked;
  for (int id = 0; id < piece_count; ++id) ranked.emplace_back(piece_area[static_cast<size_t>(id)], id);
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
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) removed[static_cast<size_t>(f)] = piece[static_cast<size_t>(f)] != ranked[0].second;
  mesh_detail::drop_faces(mesh, removed);
  mesh_detail::drop_unreferenced_vertices(mesh);
  // Dropping renumbers faces and vertices: the topology of the mesh as it now is.
  topology = build_mesh_topology(mesh.F, mesh.V.rows());
}

int orient_outward(TriMesh& mesh, MeshTopology& topology, IntakeReport& report) {
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
        const int next = topology.face_across(static_cast<int>(corner));
        if (next < 0) continue;
        const signed char wanted = static_cast<signed char>(flip[static_cast<size_t>(face)] ^ topology.same_direction[corner]);
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
  bool turned = flipped > 0;
  if (signed_volume_mm3(mesh) < 0.0) {
    mesh.F.col(1).swap(mesh.F.col(2));
    flipped = static_cast<int>(mesh.F.rows()) - flipped;
    turned = true;
  }
  // A turned face lists its corners the other way: its half-edges, and who is across them, change.
  if (turned) topology = build_mesh_topology(mesh.F, mesh.V.rows());
  return flipped;
}

int count_boundary_loops(const MeshTopology& topology) {
  return static_cast<int>(topology.boundary_loops.size()) + topology.open_boundary_chains;
}

}  // namespace lastcut
