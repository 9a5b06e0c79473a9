// Bi-Laplacian fairing of chosen vertices; see bilaplacian_fairing.hpp.
#include "engine/mesh/bilaplacian_fairing.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>

#include "engine/core/engine_error.hpp"
#include "engine/core/mesh_topology.hpp"

namespace lastcut {

void fair_vertices_bilaplacian(TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& free,
                               const std::vector<Eigen::Vector3d>& directions) {
  if (free.empty()) return;
  const Eigen::Index vertex_count = mesh.V.rows();
  if (topology.vertex_count() != vertex_count || topology.face_count() != mesh.F.rows())
    throw EngineError("hole fairing: the mesh topology was built for another mesh");

  // The scale-dependent umbrella operator as a sparse matrix: U = A - I with A the neighbours' average
  // weighted by inverse edge length (Desbrun et al. 1999), so that denser sampling on one side of a
  // vertex (patch rings against scan triangles) does not pull it sideways.
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(topology.neighbors.size() + static_cast<size_t>(vertex_count));
  for (Eigen::Index v = 0; v < vertex_count; ++v) {
    const int begin = topology.neighbor_offsets[v], end = topology.neighbor_offsets[v + 1];
    double total = 0.0;
    for (int i = begin; i < end; ++i) total += 1.0 / std::max((mesh.V.row(topology.neighbors[i]) - mesh.V.row(v)).norm(), 1e-9);
    entries.emplace_back(v, v, -1.0);
    for (int i = begin; i < end; ++i)
      entries.emplace_back(v, topology.neighbors[i],
                           1.0 / std::max((mesh.V.row(topology.neighbors[i]) - mesh.V.row(v)).norm(), 1e-9) / total);
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> umbrella(vertex_count, vertex_count);
  umbrella.setFromTriplets(entries.begin(), entries.end());

  // Rows of U for the free vertices, times U: the bi-Laplacian condition at each free vertex.
  std::vector<int> column_of(static_cast<size_t>(vertex_count), -1);
  std::vector<Eigen::Triplet<double>> selected;
  for (size_t i = 0; i < free.size(); ++i) {
    column_of[free[i]] = static_cast<int>(i);
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(umbrella, free[i]); it; ++it)
      selected.emplace_back(static_cast<int>(i), it.col(), it.value());
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> free_rows(static_cast<Eigen::Index>(free.size()), vertex_count);
  free_rows.setFromTriplets(selected.begin(), selected.end());
  const Eigen::SparseMatrix<double, Eigen::RowMajor> bilaplacian = free_rows * umbrella;

  // Free columns form the system, fixed columns move to the right-hand side. Along directions, vertex
  // j is p0_j + t_j d_j and row i is projected on d_i: one unknown per vertex instead of three.
  const bool along = !directions.empty();
  if (along && directions.size() != free.size())
    throw EngineError("hole fairing: one direction per free vertex is needed");
  const Eigen::Index columns = along ? 1 : 3;
  std::vector<Eigen::Triplet<double>> system_entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(free.size()), columns);
  for (Eigen::Index row = 0; row < bilaplacian.rows(); ++row) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(bilaplacian, row); it; ++it) {
      const int column = column_of[it.col()];
      if (along) {
        const Eigen::Vector3d& d = directions[static_cast<size_t>(row)];
        if (column >= 0) system_entries.emplace_back(row, column, it.value() * d.dot(directions[column]));
        rhs(row, 0) -= it.value() * d.dot(mesh.V.row(it.col()).transpose());
      } else if (column >= 0) {
        system_entries.emplace_back(row, column, it.value());
      } else {
        rhs.row(row) -= it.value() * mesh.V.row(it.col());
      }
    }
  }
  Eigen::SparseMatrix<double> system(static_cast<Eigen::Index>(free.size()), static_cast<Eigen::Index>(free.size()));
  system.setFromTriplets(system_entries.begin(), system_entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
  solver.compute(system);
  if (solver.info() != Eigen::Success) throw EngineError("hole fairing: the patch's system is singular");
  const Eigen::MatrixXd solution = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !solution.allFinite())
    throw EngineError("hole fairing: the patch's system could not be solved");
  for (size_t i = 0; i < free.size(); ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    if (along) {
      mesh.V.row(free[i]) += solution(r, 0) * directions[i].transpose();
    } else {
      mesh.V.row(free[i]) = solution.row(r);
    }
  }
}

}  // namespace lastcut
