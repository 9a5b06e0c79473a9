#include "engine/mesh/short_edge_collapse.hpp"

#include "engine/mesh/openmesh_types.hpp"

namespace lastcut {
namespace {

using Vertex = OmMesh::VertexHandle;
using Halfedge = OmMesh::HalfedgeHandle;

// Distance of outline vertex v from the chord between its outline neighbours (0 on a straight stretch).
double corner_height(const OmMesh& mesh, Vertex v, Halfedge outline_in, Halfedge outline_out) {
  const OmMesh::Point a = mesh.point(mesh.from_vertex_handle(outline_in)), b = mesh.point(mesh.to_vertex_handle(outline_out));
  const OmMesh::Point chord = b - a;
  const double length = chord.norm();
  const OmMesh::Point offset = mesh.point(v) - a;
  return length > 0 ? OpenMesh::cross(chord, offset).norm() / length : offset.norm();
}

// The half-edge to collapse for `edge` (its from-vertex goes into its to-vertex), or an invalid one.
Halfedge collapse_direction(const OmMesh& mesh, OmMesh::EdgeHandle edge) {
  Halfedge h = mesh.halfedge_handle(edge, 0);
  const Vertex a = mesh.from_vertex_handle(h), b = mesh.to_vertex_handle(h);
  if (mesh.is_boundary(edge)) {
    const Halfedge outline = mesh.is_boundary(h) ? h : mesh.opposite_halfedge_handle(h);  // runs along the outline
    const Vertex first = mesh.from_vertex_handle(outline), second = mesh.to_vertex_handle(outline);
    const double first_height = corner_height(mesh, first, mesh.prev_halfedge_handle(outline), outline);
    const double second_height = corner_height(mesh, second, outline, mesh.next_halfedge_handle(outline));
    const Halfedge into_first = mesh.opposite_halfedge_handle(outline);
    return first_height >= second_height ? into_first : outline;
  }
  if (mesh.is_boundary(a) && mesh.is_boundary(b)) return Halfedge();  // would pinch the disk
  if (mesh.is_boundary(a)) return mesh.opposite_halfedge_handle(h);
  return h;
}

// Would moving `from` to `to_point` turn any of its triangles that survive the collapse over?
bool turns_a_triangle_over(const OmMesh& mesh, Halfedge h, const OmMesh::Point& to_point) {
  const Vertex from = mesh.from_vertex_handle(h), to = mesh.to_vertex_handle(h);
  for (const auto face : mesh.vf_range(from)) {
    OmMesh::Point before[3], after[3];
    int corner = 0;
    bool vanishes = false;
    for (const auto vertex : mesh.fv_range(face)) {
      vanishes = vanishes || vertex == to;
      before[corner] = mesh.point(vertex);
      after[corner++] = vertex == from ? to_point : mesh.point(vertex);
    }
    if (vanishes) continue;
    const OmMesh::Point normal_before = OpenMesh::cross(before[1] - before[0], before[2] - before[0]);
    const OmMesh::Point normal_after = OpenMesh::cross(after[1] - after[0], after[2] - after[0]);
    if (OpenMesh::dot(normal_before, normal_after) <= 0) return true;
  }
  return false;
}

}  // namespace

int collapse_short_edges(TriMesh& mesh, double min_edge_mm) {
  bool any_short = false;
  for (Eigen::Index f = 0; f < mesh.F.rows() && !any_short; ++f)
    for (int k = 0; k < 3; ++k)
      any_short = any_short || (mesh.V.row(mesh.F(f, k)) - mesh.V.row(mesh.F(f, (k + 1) % 3))).norm() < min_edge_mm;
  if (!any_short) return 0;
  OmMesh om = to_openmesh(mesh);
  int collapsed = 0;
  // Rounds, since a collapse can leave a neighbouring edge still short.
  for (int round = 0; round < 8; ++round) {
    int collapsed_this_round = 0;
    for (const auto edge : om.edges()) {
      if (om.status(edge).deleted() || om.calc_edge_length(edge) >= min_edge_mm) continue;
      const Halfedge h = collapse_direction(om, edge);
      if (!h.is_valid() || !om.is_collapse_ok(h)) continue;
      const Vertex from = om.from_vertex_handle(h), to = om.to_vertex_handle(h);
      const bool midpoint = !om.is_boundary(from) && !om.is_boundary(to);
      const OmMesh::Point merged = midpoint ? 0.5 * (om.point(from) + om.point(to)) : om.point(to);
      if (turns_a_triangle_over(om, h, merged) ||
          turns_a_triangle_over(om, om.opposite_halfedge_handle(h), merged))
        continue;
      om.collapse(h);
      om.set_point(to, merged);
      ++collapsed_this_round;
    }
    collapsed += collapsed_this_round;
    if (collapsed_this_round == 0) break;
  }
  om.garbage_collection();
  mesh = from_openmesh(om);
  return collapsed;
}

}  // namespace lastcut
