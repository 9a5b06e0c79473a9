// Boundary First Flattening with u = 0 on the boundary; see boundary_first_start.hpp.
#include "engine/flatten/boundary_first_start.hpp"

#include <Eigen/LU>
#include <cmath>
#include <numbers>
#include <vector>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

// Angle sums per vertex from the cotangent weights: half_weight = cot(angle) / 2 at the corner
// opposite each edge, and an angle in (0, pi) is atan2(1, cot).
std::vector<double> vertex_angle_sums(const TriangleFrames& frames, int vertex_count) {
  std::vector<double> sum(static_cast<size_t>(vertex_count), 0.0);
  for (size_t f = 0; f < frames.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) sum[frames.triangles[f][k]] += std::atan2(1.0, 2.0 * frames.half_weight[3 * f + k]);
  return sum;
}

// y = A x for the cotangent Laplacian A (x, y: #V).
std::vector<double> apply_laplacian(const TriangleFrames& frames, const std::vector<double>& x) {
  std::vector<double> y(x.size(), 0.0);
  for (size_t f = 0; f < frames.triangles.size(); ++f) {
    const auto& t = frames.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      const double flow = frames.half_weight[3 * f + k] * (x[a] - x[b]);
      y[a] += flow;
      y[b] -= flow;
    }
  }
  return y;
}

// Solves A_II x_I = rhs_I - A_IB x_B for `columns` right-hand sides with the factor of the fixed-
// boundary system; boundary values are taken from `values` (#V x columns), interior rows of `values`
// are overwritten.
void solve_dirichlet(const TriangleFrames& frames, const std::vector<char>& fixed, const ReducedLaplacian& laplacian,
                     const SparseCholesky& solver, const Eigen::MatrixXd& interior_rhs, Eigen::MatrixXd& values) {
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(laplacian.matrix.rows(), values.cols());
  for (size_t r = 0; r < laplacian.vertex_of_row.size(); ++r) {
    const int v = laplacian.vertex_of_row[r];
    if (fixed[v]) {
      rhs.row(static_cast<Eigen::Index>(r)) = values.row(v);
    } else {
      rhs.row(static_cast<Eigen::Index>(r)) = interior_rhs.row(v);
    }
  }
  for (size_t f = 0; f < frames.triangles.size(); ++f) {
    const auto& t = frames.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      const double w = frames.half_weight[3 * f + k];
      if (fixed[a] && !fixed[b]) rhs.row(laplacian.row_of_vertex[b]) += w * values.row(a);
      if (fixed[b] && !fixed[a]) rhs.row(laplacian.row_of_vertex[a]) += w * values.row(b);
    }
  }
  const Eigen::MatrixXd solution = solver.solve(rhs);
  for (size_t r = 0; r < laplacian.vertex_of_row.size(); ++r) {
    const int v = laplacian.vertex_of_row[r];
    if (!fixed[v]) values.row(v) = solution.row(static_cast<Eigen::Index>(r));
  }
}

// The closed polygon with exterior angles `turn` (at loop[i], between edge i-1 and edge i) and edge
// lengths as close to `length` as closing allows: length_i (1 + T_i . lambda) with the 2-vector lambda
// that makes sum length_i T_i vanish (least change in the sum of (change)^2 / length). #loop x 2.
Eigen::MatrixXd closed_boundary_polygon(const std::vector<double>& turn, const std::vector<double>& length) {
  const size_t count = turn.size();
  std::vector<Eigen::Vector2d> tangent(count);
  double angle = 0.0;
  Eigen::Vector2d gap = Eigen::Vector2d::Zero();
  Eigen::Matrix2d weighted = Eigen::Matrix2d::Zero();
  for (size_t i = 0; i < count; ++i) {
    if (i > 0) angle += turn[i];
    tangent[i] = Eigen::Vector2d(std::cos(angle), std::sin(angle));
    gap += length[i] * tangent[i];
    weighted += length[i] * tangent[i] * tangent[i].transpose();
  }
  const Eigen::Vector2d lambda = -weighted.inverse() * gap;
  Eigen::MatrixXd polygon(static_cast<Eigen::Index>(count), 2);
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  for (size_t i = 0; i < count; ++i) {
    polygon.row(static_cast<Eigen::Index>(i)) = at.transpose();
    at += length[i] * (1.0 + tangent[i].dot(lambda)) * tangent[i];
  }
  return polygon;
}

}  // namespace

Eigen::MatrixXd boundary_first_start(const TriMesh& mesh, const TriangleFrames& frames, const MeshTopology& topology,
                                     ReducedLaplacian& laplacian, SparseCholesky& solver) {
  if (topology.boundary_loops.empty()) throw EngineError("boundary first flattening: the surface has no boundary");
  const std::vector<int>& loop = topology.boundary_loops[0];
  const int vertex_count = mesh.vertex_count();
  std::vector<char> fixed(static_cast<size_t>(vertex_count), 0);
  for (int v : loop) fixed[v] = 1;
  assemble_laplacian(frames, frames.half_weight, fixed, laplacian);
  solver.factorize(laplacian.matrix);

  // 1. Log scale factor u: flat interior, u = 0 on the boundary.
  const std::vector<double> angle_sum = vertex_angle_sums(frames, vertex_count);
  Eigen::MatrixXd defect_rhs(vertex_count, 1);
  for (int v = 0; v < vertex_count; ++v) defect_rhs(v, 0) = -(2.0 * std::numbers::pi - angle_sum[v]);
  Eigen::MatrixXd u = Eigen::MatrixXd::Zero(vertex_count, 1);
  solve_dirichlet(frames, fixed, laplacian, solver, defect_rhs, u);

  // 2. Exterior angles of the flat boundary, 3. the closed polygon with the boundary's lengths.
  const std::vector<double> flux = apply_laplacian(frames, std::vector<double>(u.data(), u.data() + vertex_count));
  std::vector<double> turn(loop.size()), length(loop.size());
  for (size_t i = 0; i < loop.size(); ++i) {
    turn[i] = std::numbers::pi - angle_sum[loop[i]] + flux[loop[i]];
    length[i] = (mesh.V.row(loop[(i + 1) % loop.size()]) - mesh.V.row(loop[i])).norm();
  }
  const Eigen::MatrixXd polygon = closed_boundary_polygon(turn, length);

  // 4. Harmonic extension of both coordinates.
  Eigen::MatrixXd UV = Eigen::MatrixXd::Zero(vertex_count, 2);
  for (size_t i = 0; i < loop.size(); ++i) UV.row(loop[i]) = polygon.row(static_cast<Eigen::Index>(i));
  solve_dirichlet(frames, fixed, laplacian, solver, Eigen::MatrixXd::Zero(vertex_count, 2), UV);
  return UV;
}

}  // namespace lastcut
