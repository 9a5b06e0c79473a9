// Trilinear lattice subspace and its Galerkin system; see lattice_subspace.hpp.
#include "engine/flatten/lattice_subspace.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

// The lattice is a dense index of its corners; bound its size so a degenerate cell size cannot exhaust
// memory (a foot half at the default size has ~10^5 corners).
constexpr long long kMaxLatticeCorners = 16LL << 20;

}  // namespace

double lattice_cell_mm(double area_mm2, int cells) { return std::sqrt(area_mm2 / std::max(cells, 1)); }

LatticeSubspace::LatticeSubspace(const TriMesh& mesh, const ReducedLaplacian& laplacian, double cell_mm) {
  if (!(cell_mm > 0.0)) throw EngineError("lattice subspace: the cell size must be positive");
  const Eigen::RowVector3d low = mesh.V.colwise().minCoeff();
  const Eigen::RowVector3d extent = mesh.V.colwise().maxCoeff() - low;
  double cell = cell_mm;
  std::array<long long, 3> corners{};
  for (;;) {
    for (int a = 0; a < 3; ++a) corners[a] = static_cast<long long>(std::floor(extent(a) / cell)) + 2;
    if (corners[0] * corners[1] * corners[2] <= kMaxLatticeCorners) break;
    cell *= 2.0;
  }

  // Each row's 8 cube corners and trilinear weights; corners get compact node ids in order of first use.
  const Eigen::Index rows = laplacian.matrix.rows();
  std::vector<int> node_of_corner(static_cast<size_t>(corners[0] * corners[1] * corners[2]), -1);
  std::vector<int> outer(static_cast<size_t>(rows) + 1);
  std::vector<int> inner(8 * static_cast<size_t>(rows));
  std::vector<double> values(8 * static_cast<size_t>(rows));
  int nodes = 0;
  for (Eigen::Index r = 0; r < rows; ++r) {
    const int v = laplacian.vertex_of_row[static_cast<size_t>(r)];
    std::array<long long, 3> base{};
    std::array<double, 3> t{};
    for (int a = 0; a < 3; ++a) {
      const double x = (mesh.V(v, a) - low(a)) / cell;
      base[a] = std::clamp(static_cast<long long>(std::floor(x)), 0LL, corners[a] - 2);
      t[a] = std::clamp(x - static_cast<double>(base[a]), 0.0, 1.0);
    }
    std::array<std::pair<int, double>, 8> entries;
    for (int c = 0; c < 8; ++c) {
      const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
      const long long corner = (base[0] + dx) + corners[0] * ((base[1] + dy) + corners[1] * (base[2] + dz));
      int& node = node_of_corner[static_cast<size_t>(corner)];
      if (node < 0) node = nodes++;
      entries[c] = {node, (dx ? t[0] : 1.0 - t[0]) * (dy ? t[1] : 1.0 - t[1]) * (dz ? t[2] : 1.0 - t[2])};
    }
    std::sort(entries.begin(), entries.end());
    outer[static_cast<size_t>(r)] = static_cast<int>(8 * r);
    for (int c = 0; c < 8; ++c) {
      inner[8 * static_cast<size_t>(r) + c] = entries[c].first;
      values[8 * static_cast<size_t>(r) + c] = entries[c].second;
    }
  }
  outer[static_cast<size_t>(rows)] = static_cast<int>(8 * rows);
  prolongation_ = Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor>>(
      rows, nodes, 8 * rows, outer.data(), inner.data(), values.data());
  restriction_ = prolongation_.transpose();

  // Galerkin system P^T L P. A node whose cubes hold only vertices at its far corners has a tiny row;
  // a diagonal 1e-10 of the mean keeps it definite without changing the corrections measurably.
  const Eigen::SparseMatrix<double> column_prolongation = prolongation_;
  Eigen::SparseMatrix<double> coarse = restriction_ * (laplacian.matrix * column_prolongation);
  const double shift = 1e-10 * coarse.diagonal().mean();
  for (int n = 0; n < nodes; ++n) coarse.coeffRef(n, n) += shift;
  coarse_.analyze_pattern(coarse);
  coarse_.factorize(coarse);
}

Eigen::MatrixXd LatticeSubspace::correction(const Eigen::MatrixXd& residual) const {
  const Eigen::MatrixXd coarse_residual = restriction_ * residual;
  return prolongation_ * coarse_.solve(coarse_residual);
}

}  // namespace lastcut
