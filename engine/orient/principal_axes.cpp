#include "engine/orient/principal_axes.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "engine/core/engine_error.hpp"

namespace lastcut {

PrincipalAxes principal_axes(const TriMesh& mesh) {
  double total_area = 0.0;
  Eigen::Vector3d weighted_sum = Eigen::Vector3d::Zero();
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const double area = 0.5 * (b - a).cross(c - a).norm();
    total_area += area;
    weighted_sum += area * (a + b + c) / 3.0;
  }
  if (!(total_area > 0.0)) throw EngineError("the mesh has no surface area");
  PrincipalAxes result;
  result.centroid = weighted_sum / total_area;

  Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = Eigen::Vector3d(mesh.V.row(mesh.F(f, 0))) - result.centroid;
    const Eigen::Vector3d b = Eigen::Vector3d(mesh.V.row(mesh.F(f, 1))) - result.centroid;
    const Eigen::Vector3d c = Eigen::Vector3d(mesh.V.row(mesh.F(f, 2))) - result.centroid;
    const double area = 0.5 * (b - a).cross(c - a).norm();
    const Eigen::Vector3d g = (a + b + c) / 3.0;
    moment += area / 12.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + 9.0 * g * g.transpose());
  }
  moment /= total_area;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(moment);
  // Eigen sorts eigenvalues increasing; we want the longest axis first.
  for (int k = 0; k < 3; ++k) {
    result.axes.col(k) = solver.eigenvectors().col(2 - k);
    result.spread(k) = std::sqrt(std::max(0.0, solver.eigenvalues()(2 - k)));
  }
  if (result.axes.determinant() < 0.0) result.axes.col(2) = -result.axes.col(2);
  return result;
}

}  // namespace lastcut
