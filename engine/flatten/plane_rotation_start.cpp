// ARAP start map from per-triangle rotations onto the mean plane; see plane_rotation_start.hpp.
#include "engine/flatten/plane_rotation_start.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

namespace lastcut {
namespace {

// The mean normal must be at least this long relative to the total area (|sum a_t n_t| / sum a_t) for
// the half to face one way; a last half is ~0.6-0.8, a closed surface 0.
constexpr double kMinimumMeanNormalLength = 0.05;
// Triangles facing away from N by more than this (cos of the angle) have no stable smallest rotation:
// they are turned half a turn about an axis across their normal and projected instead.
constexpr double kMostOpposedCosine = -0.9;

}  // namespace

std::optional<Eigen::MatrixXd> plane_rotation_start(const TriMesh& mesh, const TriangleFrames& frames,
                                                    const MeshTopology& topology, const ReducedLaplacian& laplacian,
                                                    const SparseCholesky& factor) {
  const size_t face_count = frames.triangles.size();
  std::vector<Eigen::Vector3d> normals(face_count);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (size_t f = 0; f < face_count; ++f) {
    const auto& t = frames.triangles[f];
    const Eigen::Vector3d p0 = mesh.V.row(t[0]);
    const Eigen::Vector3d n = (Eigen::Vector3d(mesh.V.row(t[1])) - p0).cross(Eigen::Vector3d(mesh.V.row(t[2])) - p0);
    mean += 0.5 * n;  // area-weighted
    normals[f] = n.normalized();
  }
  if (!(mean.norm() > kMinimumMeanNormalLength * frames.area_mm2.sum())) return std::nullopt;
  const Eigen::Vector3d N = mean.normalized();
  // Right-handed basis (E1, E2, N) of the plane, E1 along the outline's longest chord (as the Tutte map's
  // long axis): taken from the mesh, not from the coordinate axes, so the mold does not depend on the pose.
  const int end_a = farthest_vertex_on_loop(mesh, topology.boundary_loops[0], topology.boundary_loops[0].front());
  const int end_b = farthest_vertex_on_loop(mesh, topology.boundary_loops[0], end_a);
  Eigen::Vector3d chord = mesh.V.row(end_b) - mesh.V.row(end_a);
  chord -= chord.dot(N) * N;
  const Eigen::Vector3d E1 = chord.norm() > 0.0 ? Eigen::Vector3d(chord.normalized()) : N.unitOrthogonal();
  const Eigen::Vector3d E2 = N.cross(E1);

  const int vertex_count = mesh.vertex_count();
  std::vector<double> rhs(2 * static_cast<size_t>(vertex_count), 0.0);
  for (size_t f = 0; f < face_count; ++f) {
    const auto& t = frames.triangles[f];
    const Eigen::Vector3d& n = normals[f];
    const double c = n.dot(N);
    const Eigen::Vector3d axis = n.cross(N);  // |axis| = sin of the angle
    const bool opposed = c < kMostOpposedCosine;
    const Eigen::Vector3d half_turn_axis = axis.norm() > 1e-9 ? axis.normalized() : E1;
    for (int k = 0; k < 3; ++k) {
      const int from = t[(k + 1) % 3], to = t[(k + 2) % 3];
      const Eigen::Vector3d d = mesh.V.row(to) - mesh.V.row(from);
      // Rodrigues' formula for the smallest rotation taking n to N, applied to the edge.
      const Eigen::Vector3d r = opposed ? Eigen::Vector3d(2.0 * half_turn_axis.dot(d) * half_turn_axis - d)
                                        : Eigen::Vector3d(c * d + axis.cross(d) + axis * (axis.dot(d) / (1.0 + c)));
      const double w = frames.half_weight[3 * f + k];
      const double ru = w * r.dot(E1), rv = w * r.dot(E2);
      rhs[2 * to] += ru;
      rhs[2 * to + 1] += rv;
      rhs[2 * from] -= ru;
      rhs[2 * from + 1] -= rv;
    }
  }
  // The pinned vertex sits at the origin, so it adds nothing to the other rows' right-hand sides.
  Eigen::MatrixXd reduced(laplacian.matrix.rows(), 2);
  for (Eigen::Index r = 0; r < reduced.rows(); ++r) {
    const int v = laplacian.vertex_of_row[r];
    reduced(r, 0) = rhs[2 * v];
    reduced(r, 1) = rhs[2 * v + 1];
  }
  const Eigen::MatrixXd solution = factor.solve(reduced);
  Eigen::MatrixXd UV = Eigen::MatrixXd::Zero(vertex_count, 2);
  for (Eigen::Index r = 0; r < solution.rows(); ++r) UV.row(laplacian.vertex_of_row[r]) = solution.row(r);
  return UV;
}

double area_facing_away_share(const TriMesh& mesh) {
  const Eigen::MatrixXd normals = triangle_normals(mesh);
  const Eigen::VectorXd areas = triangle_areas(mesh);
  const Eigen::Vector3d mean = (normals.array().colwise() * areas.array()).colwise().sum().transpose();
  if (!(mean.norm() > 0.0)) return 1.0;
  const Eigen::VectorXd facing = normals * mean.normalized();
  double away = 0.0;
  for (Eigen::Index f = 0; f < facing.size(); ++f)
    if (facing(f) < 0.0) away += areas(f);
  return away / areas.sum();
}

}  // namespace lastcut
