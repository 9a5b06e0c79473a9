// A piece's surface moved off the last by its material's thickness; see piece_thickness.hpp.
#include "engine/style/piece_thickness.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

// Each vertex's normal: the area-weighted mean of the triangle normals over its own triangles and those
// reached from them through shared corners whose centroids lie within kNormalRadius_mm of it (#V x 3, unit).
Eigen::MatrixXd surface_normals(const TriMesh& mesh) {
  const Eigen::Index vertex_count = mesh.V.rows(), face_count = mesh.F.rows();
  std::vector<std::vector<Eigen::Index>> faces_at(static_cast<std::size_t>(vertex_count));
  Eigen::MatrixXd area_normal(face_count, 3), centroid(face_count, 3);  // area normal: its length is twice the area
  for (Eigen::Index f = 0; f < face_count; ++f) {
    const Eigen::RowVector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    area_normal.row(f) = (b - a).cross(c - a);
    centroid.row(f) = (a + b + c) / 3;
    for (int k = 0; k < 3; ++k) faces_at[static_cast<std::size_t>(mesh.F(f, k))].push_back(f);
  }
  Eigen::MatrixXd normals = Eigen::MatrixXd::Zero(vertex_count, 3);
  std::vector<Eigen::Index> seen_by(static_cast<std::size_t>(face_count), -1), stack;
  for (Eigen::Index v = 0; v < vertex_count; ++v) {
    stack = faces_at[static_cast<std::size_t>(v)];
    for (const Eigen::Index f : stack) seen_by[static_cast<std::size_t>(f)] = v;
    while (!stack.empty()) {
      const Eigen::Index f = stack.back();
      stack.pop_back();
      normals.row(v) += area_normal.row(f);
      for (int k = 0; k < 3; ++k)
        for (const Eigen::Index g : faces_at[static_cast<std::size_t>(mesh.F(f, k))]) {
          if (seen_by[static_cast<std::size_t>(g)] == v) continue;
          seen_by[static_cast<std::size_t>(g)] = v;
          if ((centroid.row(g) - mesh.V.row(v)).norm() <= kNormalRadius_mm) stack.push_back(g);
        }
    }
    const double length = normals.row(v).norm();
    if (length > 0) normals.row(v) /= length;
  }
  return normals;
}

}  // namespace

double mid_surface_offset_mm(double thickness_mm) { return thickness_mm / 2; }

TriMesh offset_along_normals(const TriMesh& mesh, double offset_mm) {
  if (!std::isfinite(offset_mm) || offset_mm < 0) {
    std::ostringstream reason;
    reason << "a surface can only be moved outward off the last, by a finite distance, not " << offset_mm << " mm";
    throw EngineError(reason.str());
  }
  TriMesh moved = mesh;
  if (offset_mm == 0) return moved;
  moved.V += offset_mm * surface_normals(mesh);
  // A triangle of some height whose normal turned against its old one was moved through a centre of
  // curvature. A needle does not count: its turn folds nothing.
  int turned = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const auto area_normal = [&](const TriMesh& m) {
      const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
      return Eigen::Vector3d((b - a).cross(c - a));
    };
    const Eigen::Vector3d before = area_normal(mesh);
    double longest_mm = 0;
    for (int k = 0; k < 3; ++k) longest_mm = std::max(longest_mm, (mesh.V.row(mesh.F(f, k)) - mesh.V.row(mesh.F(f, (k + 1) % 3))).norm());
    const double height_mm = longest_mm > 0 ? before.norm() / longest_mm : 0;
    if (height_mm >= kNeedleHeight_mm && before.dot(area_normal(moved)) <= 0) ++turned;
  }
  if (turned > 0) {
    std::ostringstream reason;
    reason << "moved " << offset_mm << " mm off the last the surface folds (" << turned
           << " triangles turn over): the last curves inward tighter than that";
    throw EngineError(reason.str());
  }
  return moved;
}

}  // namespace lastcut
