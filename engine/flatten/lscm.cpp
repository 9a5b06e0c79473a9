// Free-boundary LSCM (Lévy et al. 2002) via the cotangent-Laplacian form of the conformal energy; see lscm.hpp.
#include "engine/flatten/lscm.hpp"

#include <chrono>
#include <cmath>
#include <vector>

#include "engine/core/engine_error.hpp"

namespace lastcut {
LscmResult lscm(const TriMesh& mesh, const TriangleFrames& frames, const MeshTopology& topology, SparseSolver solver) {
  const int n = mesh.vertex_count();
  const int pin_a = farthest_vertex_on_loop(mesh, topology.boundary_loops[0], topology.boundary_loops[0][0]);
  const int pin_b = farthest_vertex_on_loop(mesh, topology.boundary_loops[0], pin_a);
  if (pin_a == pin_b) throw EngineError("cannot flatten: all boundary vertices coincide");
  const double pin_distance = (mesh.V.row(pin_b) - mesh.V.row(pin_a)).norm();

  // Unknowns: u of every vertex, then v of every vertex, without the four pinned coordinates.
  Eigen::VectorXd known = Eigen::VectorXd::Zero(2 * n);
  known(pin_b) = pin_distance;
  std::vector<int> unknown_of(2 * n, -1);
  int unknowns = 0;
  for (int i = 0; i < 2 * n; ++i) {
    const int vertex = i % n;
    if (vertex != pin_a && vertex != pin_b) unknown_of[i] = unknowns++;
  }

  // Hessian of E_C over all 2n coordinates as triplets; pinned columns go to the right-hand side.
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(frames.triangles.size() * 24 + topology.boundary_loops[0].size() * 4);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
  auto add = [&](int row, int col, double value) {
    const int r = unknown_of[row];
    if (r < 0) return;
    const int c = unknown_of[col];
    if (c >= 0) {
      triplets.emplace_back(r, c, value);
    } else {
      rhs(r) -= value * known(col);
    }
  };
  for (size_t f = 0; f < frames.triangles.size(); ++f) {
    const auto& t = frames.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const double w = frames.half_weight[3 * f + k];
      const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      for (int offset : {0, n}) {
        add(a + offset, a + offset, w);
        add(b + offset, b + offset, w);
        add(a + offset, b + offset, -w);
        add(b + offset, a + offset, -w);
      }
    }
  }
  // -A(u, v) = -1/2 sum over boundary edges i->j of (u_i v_j - u_j v_i).
  const auto& loop = topology.boundary_loops[0];
  for (size_t e = 0; e < loop.size(); ++e) {
    const int i = loop[e], j = loop[(e + 1) % loop.size()];
    add(i, n + j, -0.5);
    add(n + j, i, -0.5);
    add(j, n + i, 0.5);
    add(n + i, j, 0.5);
  }
  Eigen::SparseMatrix<double> H(unknowns, unknowns);
  H.setFromTriplets(triplets.begin(), triplets.end());

  LscmResult result;
  const auto start = std::chrono::steady_clock::now();
  SparseCholesky factor(solver);
  factor.analyze_pattern(H);
  factor.factorize(H);
  result.seconds_factorize = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Eigen::VectorXd x = factor.solve(rhs);

  result.UV.resize(n, 2);
  for (int i = 0; i < 2 * n; ++i) {
    result.UV(i % n, i / n) = unknown_of[i] >= 0 ? x(unknown_of[i]) : known(i);
  }
  // Scale to the 3D area about the centroid.
  double area_2d = 0.0;
  for (const auto& t : frames.triangles) {
    const Eigen::Vector2d p = result.UV.row(t[1]) - result.UV.row(t[0]);
    const Eigen::Vector2d q = result.UV.row(t[2]) - result.UV.row(t[0]);
    area_2d += 0.5 * (p.x() * q.y() - p.y() * q.x());
  }
  if (!(area_2d > 0.0)) throw EngineError("LSCM produced a degenerate map: the mesh is too badly shaped");
  const Eigen::RowVector2d centroid = result.UV.colwise().mean();
  result.UV = ((result.UV.rowwise() - centroid) * std::sqrt(frames.area_mm2.sum() / area_2d)).eval();
  return result;
}

}  // namespace lastcut
