#include "engine/lastgen/scan_artifacts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/mesh/mesh_face_edits.hpp"

namespace lastcut {
double uniform01(std::mt19937_64& random) { return static_cast<double>(random() >> 11) * 0x1.0p-53; }

double standard_normal(std::mt19937_64& random) {
  const double u1 = 1.0 - uniform01(random);  // (0, 1]
  const double u2 = uniform01(random);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

void add_normal_noise(TriMesh& mesh, double sigma_mm, std::mt19937_64& random) {
  if (sigma_mm <= 0.0) return;
  const Eigen::MatrixXd normals = vertex_normals(mesh);
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) mesh.V.row(v) += sigma_mm * standard_normal(random) * normals.row(v);
}

void add_isotropic_noise(TriMesh& mesh, double sigma_mm, std::mt19937_64& random) {
  if (sigma_mm <= 0.0) return;
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    for (int axis = 0; axis < 3; ++axis) mesh.V(v, axis) += sigma_mm * standard_normal(random);
}

void punch_holes(TriMesh& mesh, int count, const std::function<bool(const Eigen::Vector3d&)>& allowed,
                 std::mt19937_64& random) {
  if (count <= 0) return;
  const Eigen::Index vertex_count = mesh.V.rows();
  std::vector<std::vector<int>> faces_of_vertex(static_cast<size_t>(vertex_count));
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) faces_of_vertex[static_cast<size_t>(mesh.F(f, c))].push_back(static_cast<int>(f));
  const double mean_edge_mm = std::sqrt(4.0 * surface_area(mesh) / (std::sqrt(3.0) * std::max<Eigen::Index>(1, mesh.F.rows())));
  const int rings = std::clamp(static_cast<int>(std::lround(2.5 / mean_edge_mm)), 1, 3);

  std::vector<int> candidates;
  for (Eigen::Index v = 0; v < vertex_count; ++v)
    if (allowed(mesh.V.row(v).transpose())) candidates.push_back(static_cast<int>(v));
  std::vector<Eigen::Vector3d> centres;
  std::vector<bool> removed(static_cast<size_t>(mesh.F.rows()), false);
  constexpr double kMinimumSpacingMm = 25.0;
  for (int attempt = 0; static_cast<int>(centres.size()) < count && attempt < 200 * count; ++attempt) {
    if (candidates.empty()) break;
    const int centre = candidates[static_cast<size_t>(uniform01(random) * static_cast<double>(candidates.size()))];
    const Eigen::Vector3d position = mesh.V.row(centre).transpose();
    const bool too_close = std::any_of(centres.begin(), centres.end(),
                                       [&](const Eigen::Vector3d& other) { return (other - position).norm() < kMinimumSpacingMm; });
    if (too_close) continue;
    // Vertices within rings - 1 steps of the centre; their incident faces make the hole.
    std::set<int> inner{centre};
    for (int ring = 1; ring < rings; ++ring) {
      std::set<int> grown = inner;
      for (const int v : inner)
        for (const int f : faces_of_vertex[static_cast<size_t>(v)])
          for (int c = 0; c < 3; ++c) grown.insert(mesh.F(f, c));
      inner = std::move(grown);
    }
    for (const int v : inner)
      for (const int f : faces_of_vertex[static_cast<size_t>(v)]) removed[static_cast<size_t>(f)] = true;
    centres.push_back(position);
  }
  if (static_cast<int>(centres.size()) < count)
    throw EngineError("no room for " + std::to_string(count) + " scan holes 25 mm apart on this last");
  Eigen::MatrixXi kept(mesh.F.rows(), 3);
  Eigen::Index rows = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    if (!removed[static_cast<size_t>(f)]) kept.row(rows++) = mesh.F.row(f);
  mesh.F = kept.topRows(rows);
  mesh_detail::drop_unreferenced_vertices(mesh);
}

Eigen::Affine3d random_pose(std::mt19937_64& random) {
  // A normalised 4D Gaussian is a uniformly distributed unit quaternion (Shoemake 1992).
  Eigen::Quaterniond rotation(standard_normal(random), standard_normal(random), standard_normal(random),
                              standard_normal(random));
  rotation.normalize();
  Eigen::Vector3d translation_mm;
  for (int axis = 0; axis < 3; ++axis) translation_mm(axis) = 300.0 * uniform01(random) - 150.0;
  Eigen::Affine3d pose = Eigen::Affine3d::Identity();
  pose.linear() = rotation.toRotationMatrix();
  pose.translation() = translation_mm;
  return pose;
}

void transform_vertices(TriMesh& mesh, const Eigen::Affine3d& transform) {
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    mesh.V.row(v) = (transform * Eigen::Vector3d(mesh.V.row(v).transpose())).transpose();
}

}  // namespace lastcut
