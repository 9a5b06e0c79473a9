#include "engine/mesh/sliver_collapse.hpp"

#include <algorithm>
#include <vector>

#include "engine/mesh/openmesh_types.hpp"

namespace lastcut {
namespace {

constexpr double kNeedleAspect = 5.0;  // longest edge of the triangle / the short edge

bool is_sliver_edge(const OmMesh& mesh, OmMesh::EdgeHandle edge, double limit_mm) {
  const double length = mesh.calc_edge_length(edge);
  if (length >= limit_mm) return false;
  for (int side = 0; side < 2; ++side) {
    const auto h = mesh.halfedge_handle(edge, side);
    if (mesh.is_boundary(h)) continue;
    const auto next = mesh.next_halfedge_handle(h);
    const double other_a = mesh.calc_edge_length(next);
    const double other_b = mesh.calc_edge_length(mesh.next_halfedge_handle(next));
    if (length * kNeedleAspect < std::max(other_a, other_b)) return true;
  }
  return false;
}

// Would merging h's ends at `merged` leave a surviving triangle without area (a needle)? Such a
// triangle has no shape to flatten; a folded one does, and the denoising unfolds it.
bool leaves_a_needle(OmMesh& mesh, OmMesh::HalfedgeHandle h, const OmMesh::Point& merged, double limit_mm) {
  const auto left = mesh.face_handle(h), right = mesh.face_handle(mesh.opposite_halfedge_handle(h));
  for (const auto moved : {mesh.from_vertex_handle(h), mesh.to_vertex_handle(h)})
    for (const auto face : mesh.vf_range(moved)) {
      if (face == left || face == right) continue;
      OmMesh::Point p[3];
      int corner = 0;
      for (const auto vertex : mesh.fv_range(face)) p[corner++] = vertex == moved ? merged : mesh.point(vertex);
      const double area2 = OpenMesh::cross(p[1] - p[0], p[2] - p[0]).norm();
      const double longest = std::max({(p[1] - p[0]).norm(), (p[2] - p[1]).norm(), (p[0] - p[2]).norm()});
      if (area2 < 0.2 * limit_mm * longest) return true;  // its height would be under a tenth of the limit
    }
  return false;
}

}  // namespace

SliverReport collapse_slivers(TriMesh& mesh, double fraction, double min_share) {
  SliverReport report;
  std::vector<double> lengths;
  lengths.reserve(static_cast<std::size_t>(3 * mesh.F.rows()));
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) lengths.push_back((mesh.V.row(mesh.F(f, k)) - mesh.V.row(mesh.F(f, (k + 1) % 3))).norm());
  if (lengths.empty()) return report;
  std::vector<double> sorted = lengths;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  report.limit_mm = fraction * sorted[sorted.size() / 2];
  // A sliver edge is short against the scan and against its own triangle: the small but well
  // shaped triangles of a finely scanned detail (the FIND foot's toes) are left alone.
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const double* l = lengths.data() + 3 * f;
    const double longest = std::max({l[0], l[1], l[2]});
    for (int k = 0; k < 3; ++k) report.short_edges += l[k] < report.limit_mm && l[k] * kNeedleAspect < longest;
  }
  if (report.short_edges <= min_share * static_cast<double>(lengths.size())) return report;

  OmMesh om = to_openmesh(mesh);
  // Rounds, since a collapse can leave a neighbouring edge still short; a fan of N rings needs a few.
  for (int round = 0; round < 8; ++round) {
    int collapsed_this_round = 0;
    for (const auto edge : om.edges()) {
      if (om.status(edge).deleted() || !is_sliver_edge(om, edge, report.limit_mm)) continue;
      const auto h = om.halfedge_handle(edge, 0);
      const auto from = om.from_vertex_handle(h), to = om.to_vertex_handle(h);
      if (om.is_boundary(from) || om.is_boundary(to) || !om.is_collapse_ok(h)) continue;
      const auto merged = 0.5 * (om.point(from) + om.point(to));
      if (leaves_a_needle(om, h, merged, report.limit_mm)) continue;
      om.collapse(h);
      om.set_point(to, merged);
      ++collapsed_this_round;
    }
    report.collapsed += collapsed_this_round;
    if (collapsed_this_round == 0) break;
  }
  om.garbage_collection();
  mesh = from_openmesh(om);
  return report;
}

}  // namespace lastcut
