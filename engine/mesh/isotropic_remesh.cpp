#include "engine/mesh/isotropic_remesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <vector>

namespace lastcut {
namespace {

using Vec = OmMesh::Point;

Eigen::Vector3d to_eigen(const Vec& p) { return {p[0], p[1], p[2]}; }
Vec to_point(const Eigen::Vector3d& p) { return Vec(p.x(), p.y(), p.z()); }

Vec face_normal_with(const OmMesh& mesh, OmMesh::FaceHandle face, OmMesh::VertexHandle moved, const Vec& moved_to) {
  std::array<Vec, 3> p;
  int c = 0;
  for (const auto vh : mesh.fv_range(face)) p[c++] = vh == moved ? moved_to : mesh.point(vh);
  return OpenMesh::cross(p[1] - p[0], p[2] - p[0]);
}

// Collapsing `h` merges its from-vertex into its to-vertex, which then sits at `merged`.
// Refused when that would create a long edge or turn a surviving triangle over (fold).
bool collapse_keeps_quality(OmMesh& mesh, OmMesh::HalfedgeHandle h, double high_mm, const Vec& merged) {
  const auto from = mesh.from_vertex_handle(h);
  const auto to = mesh.to_vertex_handle(h);
  if (mesh.is_boundary(from) || mesh.is_boundary(to)) return false;
  for (const auto moved : {from, to}) {
    for (const auto neighbour : mesh.vv_range(moved))
      if (neighbour != from && neighbour != to && (mesh.point(neighbour) - merged).norm() > high_mm) return false;
  }
  const auto left = mesh.face_handle(h);
  const auto right = mesh.face_handle(mesh.opposite_halfedge_handle(h));
  for (const auto moved : {from, to}) {
    for (const auto face : mesh.vf_range(moved)) {
      if (face == left || face == right) continue;
      const Vec before = face_normal_with(mesh, face, moved, mesh.point(moved));
      const Vec after = face_normal_with(mesh, face, moved, merged);
      const double before_norm = before.norm(), after_norm = after.norm();
      if (after_norm < 1e-12 || OpenMesh::dot(before, after) < 0.5 * before_norm * after_norm) return false;
    }
  }
  return mesh.is_collapse_ok(h);
}

// Collapses the edge into one of its ends (or its midpoint when `to_midpoint`), if quality allows.
bool try_collapse(OmMesh& mesh, OmMesh::EdgeHandle edge, double high_mm, bool to_midpoint) {
  for (int side = 0; side < 2; ++side) {
    const auto h = mesh.halfedge_handle(edge, side);
    const auto to = mesh.to_vertex_handle(h);
    const Vec merged = to_midpoint ? 0.5 * (mesh.point(to) + mesh.point(mesh.from_vertex_handle(h))) : mesh.point(to);
    if (!collapse_keeps_quality(mesh, h, high_mm, merged)) continue;
    mesh.collapse(h);
    mesh.set_point(to, merged);
    return true;
  }
  return false;
}

void split_long_edges(OmMesh& mesh, double high_mm) {
  for (size_t e = 0; e < mesh.n_edges(); ++e) {
    const OmMesh::EdgeHandle edge(static_cast<int>(e));
    if (mesh.status(edge).deleted() || mesh.is_boundary(edge) || mesh.calc_edge_length(edge) <= high_mm) continue;
    const auto h = mesh.halfedge_handle(edge, 0);
    const Vec midpoint = 0.5 * (mesh.point(mesh.to_vertex_handle(h)) + mesh.point(mesh.from_vertex_handle(h)));
    mesh.split(edge, mesh.add_vertex(midpoint));
  }
}

void collapse_short_edges(OmMesh& mesh, double low_mm, double high_mm) {
  for (size_t e = 0; e < mesh.n_edges(); ++e) {
    const OmMesh::EdgeHandle edge(static_cast<int>(e));
    if (mesh.status(edge).deleted() || mesh.calc_edge_length(edge) >= low_mm) continue;
    try_collapse(mesh, edge, high_mm, false);
  }
}

int valence_deviation(int valence) { return std::abs(valence - 6); }

void equalize_valences(OmMesh& mesh) {
  for (const auto edge : mesh.edges()) {
    if (mesh.is_boundary(edge) || !mesh.is_flip_ok(edge)) continue;
    const auto h0 = mesh.halfedge_handle(edge, 0);
    const auto h1 = mesh.halfedge_handle(edge, 1);
    const auto a = mesh.to_vertex_handle(h0), b = mesh.to_vertex_handle(h1);
    const auto c = mesh.to_vertex_handle(mesh.next_halfedge_handle(h0));
    const auto d = mesh.to_vertex_handle(mesh.next_halfedge_handle(h1));
    if (mesh.is_boundary(a) || mesh.is_boundary(b) || mesh.is_boundary(c) || mesh.is_boundary(d)) continue;
    const int va = static_cast<int>(mesh.valence(a)), vb = static_cast<int>(mesh.valence(b));
    const int vc = static_cast<int>(mesh.valence(c)), vd = static_cast<int>(mesh.valence(d));
    if (va <= 3 || vb <= 3) continue;
    const int before = valence_deviation(va) + valence_deviation(vb) + valence_deviation(vc) + valence_deviation(vd);
    const int after = valence_deviation(va - 1) + valence_deviation(vb - 1) + valence_deviation(vc + 1) +
                      valence_deviation(vd + 1);
    if (after >= before) continue;
    // Flip only across a nearly flat hinge, so that creases and fillets keep their shape.
    const Vec pa = mesh.point(a), pb = mesh.point(b), pc = mesh.point(c), pd = mesh.point(d);
    // Faces (b, a, c) and (a, b, d) become (a, c, d) and (c, b, d).
    const Vec n_before_0 = OpenMesh::cross(pa - pb, pc - pb), n_before_1 = OpenMesh::cross(pb - pa, pd - pa);
    const Vec n_after_0 = OpenMesh::cross(pc - pa, pd - pa), n_after_1 = OpenMesh::cross(pb - pc, pd - pc);
    auto cosine = [](const Vec& u, const Vec& v) {
      const double norms = u.norm() * v.norm();
      return norms > 0.0 ? OpenMesh::dot(u, v) / norms : -1.0;
    };
    if (cosine(n_before_0, n_before_1) < 0.9 || cosine(n_after_0, n_after_1) < 0.9) continue;
    if (cosine(n_after_0, n_before_0 + n_before_1) < 0.5 || cosine(n_after_1, n_before_0 + n_before_1) < 0.5) continue;
    mesh.flip(edge);
  }
}

void relax_and_project(OmMesh& mesh, const SurfaceProjection& project) {
  mesh.update_face_normals();
  mesh.update_vertex_normals();
  std::vector<Vec> moved(mesh.n_vertices());
  for (const auto vh : mesh.vertices()) {
    const Vec p = mesh.point(vh);
    moved[vh.idx()] = p;
    if (mesh.is_boundary(vh)) continue;
    // Area-weighted centroid of the one-ring triangles: evens out triangle sizes, not only edges.
    Vec centroid(0.0, 0.0, 0.0);
    double total_area = 0.0;
    for (const auto face : mesh.vf_range(vh)) {
      std::array<Vec, 3> q;
      int c = 0;
      for (const auto corner : mesh.fv_range(face)) q[c++] = mesh.point(corner);
      const double area = 0.5 * OpenMesh::cross(q[1] - q[0], q[2] - q[0]).norm();
      centroid += area * (q[0] + q[1] + q[2]) / 3.0;
      total_area += area;
    }
    if (total_area <= 0.0) continue;
    centroid /= total_area;
    const Vec normal = mesh.normal(vh);
    const Vec shift = centroid - p;
    moved[vh.idx()] = p + shift - OpenMesh::dot(shift, normal) * normal;
  }
  for (const auto vh : mesh.vertices()) {
    if (mesh.is_boundary(vh)) continue;
    mesh.set_point(vh, to_point(project(to_eigen(moved[vh.idx()]))));
  }
}

}  // namespace

void isotropic_remesh(OmMesh& mesh, double target_edge_mm, int iterations, const SurfaceProjection& project) {
  const double high_mm = 4.0 / 3.0 * target_edge_mm;
  const double low_mm = 4.0 / 5.0 * target_edge_mm;
  for (int round = 0; round < iterations; ++round) {
    split_long_edges(mesh, high_mm);
    collapse_short_edges(mesh, low_mm, high_mm);
    mesh.garbage_collection();
    equalize_valences(mesh);
    relax_and_project(mesh, project);
  }
}

void adjust_triangle_count(OmMesh& mesh, int target_triangles, int smoothing_rounds, const SurfaceProjection& project) {
  std::vector<std::pair<double, int>> edges_by_length;
  for (const auto edge : mesh.edges()) edges_by_length.emplace_back(mesh.calc_edge_length(edge), edge.idx());
  int faces = static_cast<int>(mesh.n_faces());
  double mean_length_mm = 0.0;
  for (const auto& entry : edges_by_length) mean_length_mm += entry.first;
  mean_length_mm /= std::max<size_t>(1, edges_by_length.size());
  if (faces + 1 < target_triangles) {
    std::sort(edges_by_length.begin(), edges_by_length.end(), std::greater<>());
    for (const auto& [length, index] : edges_by_length) {
      if (faces + 1 >= target_triangles) break;
      const OmMesh::EdgeHandle edge(index);
      if (mesh.is_boundary(edge)) continue;
      const auto h = mesh.halfedge_handle(edge, 0);
      const Vec midpoint = 0.5 * (mesh.point(mesh.to_vertex_handle(h)) + mesh.point(mesh.from_vertex_handle(h)));
      mesh.split(edge, mesh.add_vertex(midpoint));
      faces += 2;
    }
  } else if (faces - 1 > target_triangles) {
    std::sort(edges_by_length.begin(), edges_by_length.end());
    for (const auto& [length_mm, index] : edges_by_length) {
      if (faces - 1 <= target_triangles) break;
      const OmMesh::EdgeHandle edge(index);
      if (mesh.status(edge).deleted()) continue;
      if (try_collapse(mesh, edge, 1.6 * mean_length_mm, true)) faces -= 2;
    }
    mesh.garbage_collection();
  }
  for (int round = 0; round < smoothing_rounds; ++round) {
    equalize_valences(mesh);
    relax_and_project(mesh, project);
  }
}

}  // namespace lastcut
