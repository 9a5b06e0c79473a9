#include "engine/mesh/mesh_repair.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <vector>

#include "engine/core/mesh_topology.hpp"
#include "engine/mesh/mesh_face_edits.hpp"

namespace lastcut {

using mesh_detail::drop_faces;
using mesh_detail::UnionFind;

int merge_duplicate_vertices(TriMesh& mesh) {
  const Eigen::Index n = mesh.V.rows();
  if (n == 0) return 0;
  const double diagonal = bounding_box_size(mesh).norm();
  const double cell = std::max(1e-7 * diagonal, 1e-12);
  const Eigen::RowVector3d low = mesh.V.colwise().minCoeff();
  std::vector<std::array<int64_t, 3>> keys(static_cast<size_t>(n));
  for (Eigen::Index v = 0; v < n; ++v)
    for (int c = 0; c < 3; ++c) keys[static_cast<size_t>(v)][c] = std::llround((mesh.V(v, c) - low(c)) / cell);
  std::vector<int> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&keys](int a, int b) { return keys[a] != keys[b] ? keys[a] < keys[b] : a < b; });
  std::vector<int> representative(static_cast<size_t>(n));
  int merged = 0;
  for (size_t k = 0; k < order.size(); ++k) {
    const int v = order[k];
    if (k > 0 && keys[static_cast<size_t>(order[k - 1])] == keys[static_cast<size_t>(v)]) {
      representative[static_cast<size_t>(v)] = representative[static_cast<size_t>(order[k - 1])];
      ++merged;
    } else {
      representative[static_cast<size_t>(v)] = v;
    }
  }
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) mesh.F(f, c) = representative[static_cast<size_t>(mesh.F(f, c))];
  mesh_detail::drop_unreferenced_vertices(mesh);
  return merged;
}

int remove_degenerate_faces(TriMesh& mesh) {
  const double diagonal = bounding_box_size(mesh).norm();
  const double min_double_area = 1e-12 * diagonal * diagonal;
  std::vector<char> removed(static_cast<size_t>(mesh.F.rows()), 0);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const int a = mesh.F(f, 0), b = mesh.F(f, 1), c = mesh.F(f, 2);
    if (a == b || b == c || a == c) {
      removed[static_cast<size_t>(f)] = 1;
      continue;
    }
    const Eigen::Vector3d pa = mesh.V.row(a), pb = mesh.V.row(b), pc = mesh.V.row(c);
    if ((pb - pa).cross(pc - pa).norm() <= min_double_area) removed[static_cast<size_t>(f)] = 1;
  }
  return drop_faces(mesh, removed);
}

int remove_duplicate_faces(TriMesh& mesh) {
  std::vector<std::pair<std::array<int, 3>, int>> sorted_faces(static_cast<size_t>(mesh.F.rows()));
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    std::array<int, 3> corners{mesh.F(f, 0), mesh.F(f, 1), mesh.F(f, 2)};
    std::sort(corners.begin(), corners.end());
    sorted_faces[static_cast<size_t>(f)] = {corners, static_cast<int>(f)};
  }
  std::sort(sorted_faces.begin(), sorted_faces.end());
  std::vector<char> removed(static_cast<size_t>(mesh.F.rows()), 0);
  for (size_t k = 1; k < sorted_faces.size(); ++k)
    if (sorted_faces[k].first == sorted_faces[k - 1].first) removed[static_cast<size_t>(sorted_faces[k].second)] = 1;
  return drop_faces(mesh, removed);
}

namespace {

// Flags every face that uses an edge shared by more than two faces.
int flag_faces_on_crowded_edges(const TriMesh& mesh, const MeshTopology& topology, std::vector<char>& removed) {
  int flagged = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    if (removed[static_cast<size_t>(f)]) continue;
    for (int c = 0; c < 3; ++c)
      if (topology.face_across(f, c) == kCrowdedEdge) {
        removed[static_cast<size_t>(f)] = 1;
        ++flagged;
        break;
      }
  }
  return flagged;
}

// At a vertex where several fans of faces touch only at the vertex (a "bow tie"), flags the faces
// of all but the largest fan. Fans: corners of one vertex joined across the manifold edges.
int flag_faces_in_extra_fans(const TriMesh& mesh, const MeshTopology& topology, std::vector<char>& removed) {
  const Eigen::Index face_count = mesh.F.rows();
  UnionFind corners(static_cast<size_t>(face_count) * 3);
  for (Eigen::Index f = 0; f < face_count; ++f)
    for (int c = 0; c < 3; ++c) {
      const auto h = static_cast<size_t>(3 * f + c);
      const int other = topology.across[h];
      if (other < 0) continue;
      // The edge runs from corner c to c + 1 of f; join each end with the same vertex in g, whose
      // half-edge on it starts at corner j and runs the same way or against f's.
      const int g = other / 3, j = other % 3;
      const int corner_a = topology.same_direction[h] ? j : (j + 1) % 3;
      const int corner_b = topology.same_direction[h] ? (j + 1) % 3 : j;
      corners.unite(static_cast<int>(3 * f + c), 3 * g + corner_a);
      corners.unite(static_cast<int>(3 * f + (c + 1) % 3), 3 * g + corner_b);
    }
  std::vector<int> fan_size(static_cast<size_t>(face_count) * 3, 0);
  std::vector<int> largest_root(static_cast<size_t>(mesh.V.rows()), -1);
  for (Eigen::Index f = 0; f < face_count; ++f)
    if (!removed[static_cast<size_t>(f)])
      for (int c = 0; c < 3; ++c) ++fan_size[static_cast<size_t>(corners.find(static_cast<int>(3 * f + c)))];
  for (Eigen::Index f = 0; f < face_count; ++f) {
    if (removed[static_cast<size_t>(f)]) continue;
    for (int c = 0; c < 3; ++c) {
      const int root = corners.find(static_cast<int>(3 * f + c));
      int& best = largest_root[static_cast<size_t>(mesh.F(f, c))];
      if (best < 0 || fan_size[static_cast<size_t>(root)] > fan_size[static_cast<size_t>(best)] ||
          (fan_size[static_cast<size_t>(root)] == fan_size[static_cast<size_t>(best)] && root < best))
        best = root;
    }
  }
  std::vector<char> flag_now(static_cast<size_t>(face_count), 0);
  for (Eigen::Index f = 0; f < face_count; ++f) {
    if (removed[static_cast<size_t>(f)]) continue;
    for (int c = 0; c < 3; ++c)
      if (corners.find(static_cast<int>(3 * f + c)) != largest_root[static_cast<size_t>(mesh.F(f, c))]) flag_now[static_cast<size_t>(f)] = 1;
  }
  int flagged = 0;
  for (size_t f = 0; f < flag_now.size(); ++f)
    if (flag_now[f]) {
      removed[f] = 1;
      ++flagged;
    }
  return flagged;
}

}  // namespace

int remove_non_manifold_faces(TriMesh& mesh, MeshTopology& topology) {
  std::vector<char> removed(static_cast<size_t>(mesh.F.rows()), 0);
  // Removing faces can leave a new bow tie behind; a few rounds settle every case seen in scans.
  // The topology leaves the flagged faces out, so it is rebuilt after each step that flagged some.
  for (int round = 0; round < 4; ++round) {
    topology = build_mesh_topology(mesh.F, mesh.V.rows(), removed);
    const int crowded = flag_faces_on_crowded_edges(mesh, topology, removed);
    if (crowded > 0) topology = build_mesh_topology(mesh.F, mesh.V.rows(), removed);
    const int fans = flag_faces_in_extra_fans(mesh, topology, removed);
    // No new fan: another round would rebuild this same topology and flag nothing (every face of a
    // crowded edge is flagged, and leaving faces out never crowds an edge).
    if (fans == 0) break;
  }
  const int dropped = drop_faces(mesh, removed);
  mesh_detail::drop_unreferenced_vertices(mesh);
  // Dropping renumbers faces and vertices: the topology of the mesh as it now is.
  if (dropped > 0) topology = build_mesh_topology(mesh.F, mesh.V.rows());
  return dropped;
}

}  // namespace lastcut
