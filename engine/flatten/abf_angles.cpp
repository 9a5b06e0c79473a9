// ABF++ angle solve: Newton on the Lagrangian with the block elimination of Sheffer et al. 2005; see abf_angles.hpp.
#include "engine/flatten/abf_angles.hpp"

#include <Eigen/Geometry>
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

constexpr double kPi = std::numbers::pi;

// Vertex multiplier rows: planarity of interior vertex i at 2 i, its wheel at 2 i + 1.
struct VertexRows {
  std::vector<int> interior_index;  // #V, -1 on the boundary
  int count = 0;                    // 2 #interior
};

VertexRows vertex_rows(const MeshTopology& topology) {
  const std::vector<char> interior = interior_vertices(topology);
  VertexRows rows;
  rows.interior_index.assign(interior.size(), -1);
  int next = 0;
  for (size_t v = 0; v < interior.size(); ++v)
    if (interior[v]) rows.interior_index[v] = next++;
  rows.count = 2 * next;
  return rows;
}

// Local rows of triangle f: plan(t0), wheel(t0), plan(t1), wheel(t1), plan(t2), wheel(t2); -1 on the boundary.
std::array<int, 6> local_rows(const Eigen::MatrixXi& F, const VertexRows& rows, Eigen::Index f) {
  std::array<int, 6> r{};
  for (int j = 0; j < 3; ++j) {
    const int i = rows.interior_index[static_cast<size_t>(F(f, j))];
    r[2 * j] = i < 0 ? -1 : 2 * i;
    r[2 * j + 1] = i < 0 ? -1 : 2 * i + 1;
  }
  return r;
}

// Jacobian of the vertex constraints restricted to triangle f: J(local row, corner k), 6 x 3.
// Corner k is the "next" corner of vertex t[k+2] (+cot) and the "prev" corner of vertex t[k+1] (-cot).
Eigen::Matrix<double, 6, 3> local_vertex_jacobian(const double* cot) {
  Eigen::Matrix<double, 6, 3> J = Eigen::Matrix<double, 6, 3>::Zero();
  for (int k = 0; k < 3; ++k) {
    J(2 * k, k) = 1.0;
    J(2 * ((k + 2) % 3) + 1, k) = cot[k];
    J(2 * ((k + 1) % 3) + 1, k) = -cot[k];
  }
  return J;
}

// The reduced matrix's pattern (vertex adjacency in 2x2 blocks over interior vertices) and the value slot of
// each of the 36 local entries of every triangle (-1 where a row is on the boundary).
struct ReducedPattern {
  Eigen::SparseMatrix<double> matrix;
  std::vector<int> slot;  // 36 #F, local (row a, col b) at 36 f + 6 b + a
};

ReducedPattern reduced_pattern(const Eigen::MatrixXi& F, const VertexRows& rows) {
  ReducedPattern p;
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(36 * static_cast<size_t>(F.rows()));
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const auto r = local_rows(F, rows, f);
    for (int b = 0; b < 6; ++b)
      for (int a = 0; a < 6; ++a)
        if (r[a] >= 0 && r[b] >= 0) triplets.emplace_back(r[a], r[b], 1.0);
  }
  p.matrix.resize(rows.count, rows.count);
  p.matrix.setFromTriplets(triplets.begin(), triplets.end());
  p.matrix.makeCompressed();
  const int* outer = p.matrix.outerIndexPtr();
  const int* inner = p.matrix.innerIndexPtr();
  p.slot.assign(36 * static_cast<size_t>(F.rows()), -1);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const auto r = local_rows(F, rows, f);
    for (int b = 0; b < 6; ++b)
      for (int a = 0; a < 6; ++a)
        if (r[a] >= 0 && r[b] >= 0)
          p.slot[36 * static_cast<size_t>(f) + 6 * b + a] =
              static_cast<int>(std::lower_bound(inner + outer[r[b]], inner + outer[r[b] + 1], r[a]) - inner);
  }
  return p;
}

// Gradient of the Lagrangian: in alpha (3 #F) and the constraint residuals (triangle #F, vertex rows).
struct Gradient {
  std::vector<double> alpha, triangle, vertex;
  double norm = 0;
};

Gradient lagrangian_gradient(const Eigen::MatrixXi& F, const VertexRows& rows, const std::vector<double>& alpha,
                             const std::vector<double>& beta, const std::vector<double>& cot,
                             const std::vector<double>& lambda_triangle, const std::vector<double>& lambda_vertex) {
  Gradient g;
  g.alpha.assign(alpha.size(), 0.0);
  g.triangle.assign(static_cast<size_t>(F.rows()), -kPi);
  g.vertex.assign(static_cast<size_t>(rows.count), 0.0);
  for (size_t i = 0; i < g.vertex.size(); i += 2) g.vertex[i] = -2.0 * kPi;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const auto r = local_rows(F, rows, f);
    for (int k = 0; k < 3; ++k) {
      const size_t c = 3 * static_cast<size_t>(f) + static_cast<size_t>(k);
      const int next_of = r[2 * ((k + 2) % 3) + 1], prev_of = r[2 * ((k + 1) % 3) + 1];
      double gc = 2.0 * (alpha[c] - beta[c]) / (beta[c] * beta[c]) + lambda_triangle[static_cast<size_t>(f)];
      if (r[2 * k] >= 0) {
        gc += lambda_vertex[static_cast<size_t>(r[2 * k])];
        g.vertex[static_cast<size_t>(r[2 * k])] += alpha[c];
      }
      const double log_sin = std::log(std::sin(alpha[c]));
      if (next_of >= 0) {
        gc += lambda_vertex[static_cast<size_t>(next_of)] * cot[c];
        g.vertex[static_cast<size_t>(next_of)] += log_sin;
      }
      if (prev_of >= 0) {
        gc -= lambda_vertex[static_cast<size_t>(prev_of)] * cot[c];
        g.vertex[static_cast<size_t>(prev_of)] -= log_sin;
      }
      g.alpha[c] = gc;
      g.triangle[static_cast<size_t>(f)] += alpha[c];
    }
  }
  double sum = 0.0;
  for (const auto* part : {&g.alpha, &g.triangle, &g.vertex})
    for (double x : *part) sum += x * x;
  g.norm = std::sqrt(sum);
  return g;
}

}  // namespace

std::vector<char> interior_vertices(const MeshTopology& topology) {
  std::vector<char> interior(static_cast<size_t>(topology.vertex_count()), 1);
  for (const auto& loop : topology.boundary_loops)
    for (int v : loop) interior[static_cast<size_t>(v)] = 0;
  return interior;
}

std::vector<double> abf_optimal_angles(const TriMesh& mesh, const MeshTopology& topology) {
  const Eigen::Index face_count = mesh.F.rows();
  std::vector<double> beta(3 * static_cast<size_t>(face_count));
  std::vector<double> angle_sum(static_cast<size_t>(mesh.V.rows()), 0.0);
  for (Eigen::Index f = 0; f < face_count; ++f) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d p = mesh.V.row(mesh.F(f, k));
      const Eigen::Vector3d a = mesh.V.row(mesh.F(f, (k + 1) % 3)).transpose() - p;
      const Eigen::Vector3d b = mesh.V.row(mesh.F(f, (k + 2) % 3)).transpose() - p;
      // atan2 of |a x b| and a.b: accurate for small and obtuse angles alike.
      const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
      if (!(angle > 0.0 && angle < kPi))
        throw EngineError("triangle " + std::to_string(f) + " has zero area: repair the mesh before flattening");
      beta[3 * static_cast<size_t>(f) + static_cast<size_t>(k)] = angle;
      angle_sum[static_cast<size_t>(mesh.F(f, k))] += angle;
    }
  }
  const std::vector<char> interior = interior_vertices(topology);
  for (Eigen::Index f = 0; f < face_count; ++f)
    for (int k = 0; k < 3; ++k) {
      const auto v = static_cast<size_t>(mesh.F(f, k));
      if (interior[v]) beta[3 * static_cast<size_t>(f) + static_cast<size_t>(k)] *= 2.0 * kPi / angle_sum[v];
    }
  return beta;
}

AbfAngles solve_abf_angles(const Eigen::MatrixXi& F, const MeshTopology& topology, const std::vector<double>& beta,
                           const std::vector<double>& alpha_start, const AbfOptions& options) {
  const size_t corners = 3 * static_cast<size_t>(F.rows());
  if (beta.size() != corners || alpha_start.size() != corners)
    throw EngineError("ABF++: angle arrays do not match the triangle count");
  if (options.max_newton_iterations < 0) throw EngineError("ABF++: max Newton iterations must not be negative");
  for (size_t c = 0; c < corners; ++c)
    if (!(beta[c] > 0.0 && alpha_start[c] > 0.0 && alpha_start[c] < kPi))
      throw EngineError("ABF++: corner angle " + std::to_string(c) + " is outside (0, pi)");

  const VertexRows rows = vertex_rows(topology);
  // Built at the first Newton step: angles that already meet the constraints (a developable patch) need none.
  ReducedPattern pattern;
  // Nested dissection: on the 2x2-block system of a 100k-triangle half it cut the CPU time of the angle
  // solve from 2.8-3.0 s (AMD) to 2.2 s (docs/abf.md); the eigen-ldlt backend ignores it.
  SparseCholesky factor(options.solver, FillOrdering::NestedDissection);

  AbfAngles result;
  result.beta = beta;
  std::vector<double> alpha = alpha_start;
  std::vector<double> lambda_triangle(static_cast<size_t>(F.rows()), 0.0);
  std::vector<double> lambda_vertex(static_cast<size_t>(rows.count), 0.0);
  std::vector<double> cot(corners), inv_hessian(corners), step(corners);
  std::vector<double> lambda_triangle_step(static_cast<size_t>(F.rows()));
  // Per triangle: b1* = sum_c Lambda^-1_c b1_c - b2 (the triangle multiplier's reduced right-hand side) and
  // s = sum_c Lambda^-1_c (J_tri Lambda^-1 J_tri^T, diagonal).
  std::vector<double> triangle_rhs(static_cast<size_t>(F.rows())), triangle_s(static_cast<size_t>(F.rows()));
  result.gradient_norm = -1.0;

  for (int iteration = 0;; ++iteration) {
    for (size_t c = 0; c < corners; ++c) cot[c] = 1.0 / std::tan(alpha[c]);
    const Gradient g = lagrangian_gradient(F, rows, alpha, beta, cot, lambda_triangle, lambda_vertex);
    if (!std::isfinite(g.norm)) break;
    if (result.gradient_norm < 0.0 || g.norm < result.gradient_norm) {
      result.alpha = alpha;
      result.gradient_norm = g.norm;
    }
    if (g.norm <= options.gradient_tolerance) {
      result.converged = true;
      break;
    }
    if (iteration >= options.max_newton_iterations) break;

    if (iteration == 0) {
      pattern = reduced_pattern(F, rows);
      if (rows.count > 0) factor.analyze_pattern(pattern.matrix);
    }

    // Lambda: the Hessian of L in alpha is diagonal (see the header); kept >= 1 / beta^2 so the step is a descent.
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
      const auto r = local_rows(F, rows, f);
      for (int k = 0; k < 3; ++k) {
        const size_t c = 3 * static_cast<size_t>(f) + static_cast<size_t>(k);
        const int next_of = r[2 * ((k + 2) % 3) + 1], prev_of = r[2 * ((k + 1) % 3) + 1];
        const double w = 1.0 / (beta[c] * beta[c]);
        double wheel = 0.0;
        if (next_of >= 0) wheel += lambda_vertex[static_cast<size_t>(next_of)];
        if (prev_of >= 0) wheel -= lambda_vertex[static_cast<size_t>(prev_of)];
        const double sin_a = std::sin(alpha[c]);
        inv_hessian[c] = 1.0 / std::max(2.0 * w - wheel / (sin_a * sin_a), w);
      }
    }

    // Reduced system M dlambda_vertex = rhs, M = sum_t J_t P_t J_t^T, P_t = D - d d^T / s (see the header).
    double* values = pattern.matrix.valuePtr();
    std::fill_n(values, pattern.matrix.nonZeros(), 0.0);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(rows.count);
    for (size_t i = 0; i < g.vertex.size(); ++i) rhs(static_cast<Eigen::Index>(i)) = g.vertex[i];  // -b3
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
      const size_t c0 = 3 * static_cast<size_t>(f);
      const Eigen::Vector3d d(inv_hessian[c0], inv_hessian[c0 + 1], inv_hessian[c0 + 2]);
      const Eigen::Vector3d b1(-g.alpha[c0], -g.alpha[c0 + 1], -g.alpha[c0 + 2]);
      const double s = d.sum();
      const double b1_star = d.dot(b1) + g.triangle[static_cast<size_t>(f)];
      triangle_s[static_cast<size_t>(f)] = s;
      triangle_rhs[static_cast<size_t>(f)] = b1_star;
      const auto r = local_rows(F, rows, f);
      if (std::all_of(r.begin(), r.end(), [](int x) { return x < 0; })) continue;
      const Eigen::Matrix<double, 6, 3> J = local_vertex_jacobian(&cot[c0]);
      const Eigen::Matrix3d P = Eigen::Matrix3d(d.asDiagonal()) - d * d.transpose() / s;
      const Eigen::Matrix<double, 6, 6> M = J * P * J.transpose();
      const Eigen::Matrix<double, 6, 1> local_rhs = J * (d.cwiseProduct(b1) - d * (b1_star / s));
      const int* slot = &pattern.slot[36 * static_cast<size_t>(f)];
      for (int b = 0; b < 6; ++b) {
        if (r[b] < 0) continue;
        rhs(r[b]) += local_rhs(b);
        for (int a = 0; a < 6; ++a)
          if (slot[6 * b + a] >= 0) values[slot[6 * b + a]] += M(a, b);
      }
    }
    Eigen::VectorXd dlambda_vertex = Eigen::VectorXd::Zero(rows.count);
    if (rows.count > 0) {
      factor.factorize(pattern.matrix);
      dlambda_vertex = factor.solve(rhs);
    }

    // Back substitution: the triangle multipliers, then the angles.
    double shortest = 1.0;
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
      const size_t c0 = 3 * static_cast<size_t>(f);
      const auto r = local_rows(F, rows, f);
      const Eigen::Matrix<double, 6, 3> J = local_vertex_jacobian(&cot[c0]);
      Eigen::Matrix<double, 6, 1> y = Eigen::Matrix<double, 6, 1>::Zero();
      for (int a = 0; a < 6; ++a)
        if (r[a] >= 0) y(a) = dlambda_vertex(r[a]);
      const Eigen::Vector3d Jty = J.transpose() * y;
      const Eigen::Vector3d d(inv_hessian[c0], inv_hessian[c0 + 1], inv_hessian[c0 + 2]);
      const double dlt = (triangle_rhs[static_cast<size_t>(f)] - d.dot(Jty)) / triangle_s[static_cast<size_t>(f)];
      lambda_triangle_step[static_cast<size_t>(f)] = dlt;
      for (int k = 0; k < 3; ++k) {
        const size_t c = c0 + static_cast<size_t>(k);
        step[c] = d(k) * (-g.alpha[c] - dlt - Jty(k));
        // Positivity: move at most half the way to 0 or pi.
        if (step[c] < 0.0) shortest = std::min(shortest, 0.5 * alpha[c] / -step[c]);
        if (step[c] > 0.0) shortest = std::min(shortest, 0.5 * (kPi - alpha[c]) / step[c]);
      }
    }
    if (shortest < 1.0) ++result.shortened_steps;
    for (size_t c = 0; c < corners; ++c) alpha[c] += shortest * step[c];
    for (size_t t = 0; t < lambda_triangle.size(); ++t) lambda_triangle[t] += shortest * lambda_triangle_step[t];
    for (Eigen::Index i = 0; i < rows.count; ++i) lambda_vertex[static_cast<size_t>(i)] += shortest * dlambda_vertex(i);
    result.iterations = iteration + 1;
  }
  if (result.alpha.empty()) result.alpha = alpha_start;  // only if the start itself was not finite
  return result;
}

AbfAngles solve_abf_angles(const TriMesh& mesh, const MeshTopology& topology, const AbfOptions& options) {
  const std::vector<double> beta = abf_optimal_angles(mesh, topology);
  return solve_abf_angles(mesh.F, topology, beta, beta, options);
}

AbfResiduals abf_residuals(const Eigen::MatrixXi& F, const MeshTopology& topology, const std::vector<double>& alpha) {
  const VertexRows rows = vertex_rows(topology);
  const std::vector<double> zero_triangle(static_cast<size_t>(F.rows()), 0.0), zero_vertex(rows.count, 0.0);
  std::vector<double> cot(alpha.size());
  for (size_t c = 0; c < alpha.size(); ++c) cot[c] = 1.0 / std::tan(alpha[c]);
  // With zero multipliers and beta = alpha the gradient's constraint parts are the residuals themselves.
  const Gradient g = lagrangian_gradient(F, rows, alpha, alpha, cot, zero_triangle, zero_vertex);
  AbfResiduals residuals;
  for (double x : g.triangle) residuals.triangle_rad = std::max(residuals.triangle_rad, std::abs(x));
  for (size_t i = 0; i < g.vertex.size(); ++i) {
    double& worst = i % 2 == 0 ? residuals.vertex_rad : residuals.wheel;
    worst = std::max(worst, std::abs(g.vertex[i]));
  }
  return residuals;
}

}  // namespace lastcut
