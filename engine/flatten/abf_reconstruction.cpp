// Least-squares map from corner angles (ABF++ section 5); see abf_reconstruction.hpp.
#include "engine/flatten/abf_reconstruction.hpp"

#include <Eigen/SparseCore>
#include <cmath>
#include <string>

#include "engine/core/engine_error.hpp"
#include "engine/flatten/disk_topology.hpp"

namespace lastcut {

Eigen::MatrixXd reconstruct_from_angles(const TriMesh& mesh, const MeshTopology& topology,
                                        const std::vector<double>& alpha, SparseSolver solver) {
  const int n = mesh.vertex_count();
  const Eigen::Index face_count = mesh.F.rows();
  if (alpha.size() != 3 * static_cast<size_t>(face_count))
    throw EngineError("ABF++: angle array does not match the triangle count");
  const auto& loop = topology.boundary_loops[0];
  const int pin_a = farthest_vertex_on_loop(mesh, loop, loop[0]);
  const int pin_b = farthest_vertex_on_loop(mesh, loop, pin_a);
  if (pin_a == pin_b) throw EngineError("cannot flatten: all boundary vertices coincide");

  // Coordinates: x of vertex v at 2 v, y at 2 v + 1; the four pinned ones are known.
  Eigen::VectorXd known = Eigen::VectorXd::Zero(2 * n);
  known(2 * pin_b) = (mesh.V.row(pin_b) - mesh.V.row(pin_a)).norm();
  std::vector<int> unknown_of(2 * static_cast<size_t>(n), -1);
  int unknowns = 0;
  for (int i = 0; i < 2 * n; ++i)
    if (i / 2 != pin_a && i / 2 != pin_b) unknown_of[static_cast<size_t>(i)] = unknowns++;

  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(10 * static_cast<size_t>(face_count));
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * face_count);
  auto add = [&](Eigen::Index equation, int coordinate, double value) {
    const int column = unknown_of[static_cast<size_t>(coordinate)];
    if (column >= 0) {
      triplets.emplace_back(static_cast<int>(equation), column, value);
    } else {
      rhs(equation) -= value * known(coordinate);
    }
  };
  for (Eigen::Index f = 0; f < face_count; ++f) {
    const double* angle = &alpha[3 * static_cast<size_t>(f)];
    int k = 0;  // corner a; c = k + 2 gets the largest sine
    for (int j = 1; j < 3; ++j)
      if (std::sin(angle[(j + 2) % 3]) > std::sin(angle[(k + 2) % 3])) k = j;
    const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3), c = mesh.F(f, (k + 2) % 3);
    const double ratio = std::sin(angle[(k + 1) % 3]) / std::sin(angle[(k + 2) % 3]);
    const double cs = ratio * std::cos(angle[k]), sn = ratio * std::sin(angle[k]);
    // c - a - R(alpha_a) ratio (b - a) = 0, x then y.
    const Eigen::Index ex = 2 * f, ey = 2 * f + 1;
    add(ex, 2 * c, 1.0);
    add(ex, 2 * a, cs - 1.0);
    add(ex, 2 * b, -cs);
    add(ex, 2 * a + 1, -sn);
    add(ex, 2 * b + 1, sn);
    add(ey, 2 * c + 1, 1.0);
    add(ey, 2 * a + 1, cs - 1.0);
    add(ey, 2 * b + 1, -cs);
    add(ey, 2 * a, sn);
    add(ey, 2 * b, -sn);
  }
  Eigen::SparseMatrix<double> A(2 * face_count, unknowns);
  A.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SparseMatrix<double> normal = Eigen::SparseMatrix<double>(A.transpose()) * A;
  SparseCholesky factor(solver, FillOrdering::NestedDissection);  // as for the angle system (abf_angles.cpp)
  factor.analyze_pattern(normal);
  factor.factorize(normal);
  const Eigen::VectorXd x = factor.solve(A.transpose() * rhs);

  Eigen::MatrixXd UV(n, 2);
  for (int i = 0; i < 2 * n; ++i) {
    const int column = unknown_of[static_cast<size_t>(i)];
    UV(i / 2, i % 2) = column >= 0 ? x(column) : known(i);
  }
  double area_2d = 0.0;
  for (Eigen::Index f = 0; f < face_count; ++f) {
    const Eigen::Vector2d p = UV.row(mesh.F(f, 1)) - UV.row(mesh.F(f, 0));
    const Eigen::Vector2d q = UV.row(mesh.F(f, 2)) - UV.row(mesh.F(f, 0));
    area_2d += 0.5 * (p.x() * q.y() - p.y() * q.x());
  }
  if (!(area_2d > 0.0) || !UV.allFinite())
    throw EngineError("ABF++ produced a degenerate map: the mesh is too badly shaped");
  const Eigen::RowVector2d centroid = UV.colwise().mean();
  return ((UV.rowwise() - centroid) * std::sqrt(surface_area(mesh) / area_2d)).eval();
}

}  // namespace lastcut
