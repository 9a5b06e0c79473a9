#include "engine/lastgen/stitching_seam.hpp"

#include <Eigen/Geometry>

#include "engine/lastgen/scan_artifacts.hpp"
#include "engine/segment/level_set_cut.hpp"

namespace lastcut {
namespace {

// A unit vector in a uniformly random direction.
Eigen::Vector3d random_direction(std::mt19937_64& random) {
  Eigen::Vector3d direction;
  do {
    for (int axis = 0; axis < 3; ++axis) direction(axis) = standard_normal(random);
  } while (direction.norm() < 1e-6);
  return direction.normalized();
}

}  // namespace

void add_stitching_seams(TriMesh& mesh, int count, double misregistration_mm, std::mt19937_64& random) {
  if (count <= 0 || mesh.V.rows() == 0) return;
  const Eigen::Vector3d centroid = mesh.V.colwise().mean().transpose();
  const Eigen::Vector3d extent = (mesh.V.colwise().maxCoeff() - mesh.V.colwise().minCoeff()).transpose();
  for (int seam = 0; seam < count; ++seam) {
    // Through the middle half of the last, so the seam crosses it rather than grazing an end.
    Eigen::Vector3d point = centroid;
    for (int axis = 0; axis < 3; ++axis)
      point(axis) += 0.25 * extent(axis) * (2.0 * uniform01(random) - 1.0);
    const Eigen::Vector3d normal = random_direction(random);
    // The seam is the plane's zero level set, cut into the mesh without snapping: the zipper's
    // thin triangles are what a merged scan has.
    Eigen::MatrixXd height = (mesh.V.rowwise() - point.transpose()) * normal;
    cut_along_zero_level(mesh, height, 0, 0.0);
    // Half the error as a turn (its lever: 100 mm, about half a last), half as a shift.
    const Eigen::AngleAxisd turn(0.5 * misregistration_mm / 100.0, random_direction(random));
    const Eigen::Vector3d shift = 0.5 * misregistration_mm * random_direction(random);
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
      if (height(v, 0) < 0.0) continue;  // the first pass stays
      const Eigen::Vector3d x = mesh.V.row(v).transpose();
      const Eigen::Vector3d moved = point + turn * (x - point) + shift;
      mesh.V.row(v) = (height(v, 0) > 0.0 ? moved : 0.5 * (x + moved)).transpose();  // the seam: half
    }
  }
}

}  // namespace lastcut
