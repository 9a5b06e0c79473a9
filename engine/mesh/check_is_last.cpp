// check_is_last: a cheap plausibility test of a repaired scan before hours of cutting depend on
// it. Extents are measured along the principal axes of the surface, so the pose does not matter.
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cstdio>
#include <string>

#include "engine/core/engine_error.hpp"
#include "engine/mesh/read_mesh.hpp"

namespace lastcut {

void check_is_last(const TriMesh& mesh) {
  if (mesh.F.rows() < 200)
    throw EngineError("not a shoe last: only " + std::to_string(mesh.F.rows()) + " triangles (a scan has thousands)");
  // Area-weighted principal axes of the surface.
  const Eigen::VectorXd areas = triangle_areas(mesh);
  const double total = areas.sum();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d c = (mesh.V.row(mesh.F(f, 0)) + mesh.V.row(mesh.F(f, 1)) + mesh.V.row(mesh.F(f, 2))).transpose() / 3.0;
    centre += areas(f) * c;
    second += areas(f) * c * c.transpose();
  }
  if (!(total > 0.0)) throw EngineError("not a shoe last: the surface has no area");
  centre /= total;
  const Eigen::Matrix3d covariance = second / total - centre * centre.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const Eigen::Matrix3d axes = solver.eigenvectors();  // ascending variance: thickness first
  const Eigen::MatrixXd along = (mesh.V.rowwise() - centre.transpose()) * axes;
  const Eigen::Vector3d extent = along.colwise().maxCoeff() - along.colwise().minCoeff();
  const double length_mm = extent(2), thickness_mm = extent(0);
  char text[200];
  if (length_mm < 100.0 || length_mm > 500.0) {
    std::snprintf(text, sizeof text, "not a shoe last: %.0f mm long (a last is 100..500 mm; wrong length unit?)", length_mm);
    throw EngineError(text);
  }
  if (thickness_mm < 0.15 * length_mm) {
    std::snprintf(text, sizeof text, "not a shoe last: flat, %.1f mm thick for %.0f mm long (an insole or a plate?)",
                  thickness_mm, length_mm);
    throw EngineError(text);
  }
}

}  // namespace lastcut
