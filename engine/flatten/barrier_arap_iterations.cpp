// Bijective ARAP: ARAP plus the boundary and fold barriers (Smith & Schaefer 2015, Schüller et al. 2013)
// with ARAP's Laplacian plus the barriers' curvature as the proxy Hessian; see barrier_arap_iterations.hpp.
#include "engine/flatten/barrier_arap_iterations.hpp"

#include <Eigen/SparseCore>
#include <cmath>
#include <vector>

#include "engine/flatten/anderson_acceleration.hpp"
#include "engine/flatten/arap_local_step.hpp"
#include "engine/flatten/fold_barrier.hpp"

namespace lastcut {
namespace {

enum class Trial { Accepted, Folds, Crosses, NoDecrease };

constexpr int kMostHalvings = 20;  // a step shorter than 2^-20 of the proxy step counts as a stall

// A map with its energies and the pieces the next step is built from.
struct Iterate {
  Eigen::MatrixXd UV;
  std::vector<double> rhs;       // ARAP's right-hand side for UV's best rotations (2 #V)
  std::vector<double> gradient;  // dE_B/dUV (2 #V)
  std::vector<char> state;       // TriangleState per triangle
  double arap = 0, barrier = 0;
  double total() const { return arap + barrier; }
};

// Most conjugate-gradient iterations per step and their relative residual: a line search follows the
// step, so an inexact solve suffices.
constexpr int kMostConjugateGradients = 40;
constexpr double kConjugateGradientTolerance = 1e-2;

// Delta (#V-1 x 2, reduced rows) solving (L + H / 2) Delta = R, H the barriers' curvature (rank-one terms,
// the pinned vertex left out as in L), by conjugate gradients preconditioned with L's factorization.
// Tried: a preconditioner that also holds H (the fold terms exactly, the boundary pairs by the diagonal
// bound c c^T <= |c|_1 diag(|c|), which keeps L's pattern): one more factorization per step and more
// conjugate gradients (the 40 per step all used), 5.1 s against 2.9 s on the FIND medial half, both at a
// tolerance of 1e-4. 1e-2 instead of 1e-4: 2.1 s, 213 instead of 382 conjugate gradients, the same
// D_angle (2.0102) and D_area (2.0117 against 2.0116). At most 10 per step instead of 40: the run
// stops after 6 steps at D_area 2.0152, short of the minimum; 20: the same mold, 229 against 243 in all.
Eigen::MatrixXd solve_step(const ReducedLaplacian& laplacian, const SparseCholesky& preconditioner,
                           const std::vector<BarrierCurvature>& terms, const Eigen::MatrixXd& R,
                           int& conjugate_gradients) {
  using PerColumn = Eigen::Array<double, 1, 2>;  // one scalar per column (u, v)
  // H X, with H's terms as rank-one updates; L X is never formed in the loop: for X = L^-1 Y it is Y.
  const auto apply_curvature = [&](const Eigen::MatrixXd& X, Eigen::MatrixXd& product) {
    for (const BarrierCurvature& term : terms) {
      Eigen::RowVector2d along = Eigen::RowVector2d::Zero();
      int rows[3];
      for (int k = 0; k < 3; ++k) {
        rows[k] = laplacian.row_of_vertex[term.vertex[k]];
        if (rows[k] >= 0) along += term.weight[k] * X.row(rows[k]);
      }
      for (int k = 0; k < 3; ++k) {
        if (rows[k] >= 0) product.row(rows[k]) += 0.5 * term.curvature * term.weight[k] * along;
      }
    }
  };
  Eigen::MatrixXd delta = preconditioner.solve(R);
  if (terms.empty()) return delta;  // ARAP's own global step
  Eigen::MatrixXd applied = R;  // L delta = R, so (L + H / 2) delta = R + H delta / 2
  apply_curvature(delta, applied);
  Eigen::MatrixXd residual = R - applied;
  Eigen::MatrixXd preconditioned = preconditioner.solve(residual);
  Eigen::MatrixXd direction = preconditioned;
  Eigen::MatrixXd laplacian_direction = residual;  // L direction, kept by the recursion below
  PerColumn residual_dot = (residual.array() * preconditioned.array()).colwise().sum();
  const PerColumn goal = kConjugateGradientTolerance * R.colwise().norm().array();
  for (int k = 0; k < kMostConjugateGradients; ++k) {
    if ((residual.colwise().norm().array() <= goal).all()) break;
    applied = laplacian_direction;
    apply_curvature(direction, applied);
    const PerColumn curvature_along = (direction.array() * applied.array()).colwise().sum();
    const PerColumn alpha = (curvature_along > 0.0).select(residual_dot / curvature_along, 0.0);
    delta.array() += direction.array().rowwise() * alpha;
    residual.array() -= applied.array().rowwise() * alpha;
    preconditioned = preconditioner.solve(residual);
    const PerColumn next_dot = (residual.array() * preconditioned.array()).colwise().sum();
    const PerColumn beta = (residual_dot > 0.0).select(next_dot / residual_dot, 0.0);
    direction = (preconditioned.array() + direction.array().rowwise() * beta).matrix();
    laplacian_direction = (residual.array() + laplacian_direction.array().rowwise() * beta).matrix();
    residual_dot = next_dot;
    ++conjugate_gradients;
  }
  return delta;
}

}  // namespace

BarrierArapReport run_barrier_arap_iterations(const TriangleFrames& frames, const ReducedLaplacian& laplacian,
                                              const SparseCholesky& factor, const BoundaryBarrier& barrier,
                                              const OutlineClearance& outline, Eigen::MatrixXd& UV,
                                              int max_iterations, double relative_energy_tolerance,
                                              bool accelerate) {
  BarrierArapReport report;
  const ArapLocalStep local_step(frames, laplacian);
  const FoldBarrier fold_barrier(frames, UV);
  const double negligible_energy = 1e-13 * local_step.constant_energy();

  // The energies, right-hand side and barrier gradient of `it`'s map; false when the barrier is infinite.
  const auto evaluate = [&](Iterate& it) {
    it.arap = local_step.run(it.UV, it.rhs);
    it.gradient.assign(2 * static_cast<size_t>(it.UV.rows()), 0.0);
    it.barrier = barrier.energy(it.UV, &it.gradient) + fold_barrier.energy(it.UV, &it.gradient);
    return std::isfinite(it.barrier);
  };
  // A trial replaces `now` if it folds nothing new, keeps the outline clear and lowers the energy.
  const auto judge = [&](const Iterate& now, Iterate& trial) {
    classify_triangles(frames, trial.UV, trial.state);
    if (!no_triangle_worse(now.state, trial.state)) return Trial::Folds;
    if (!outline.keeps_clear(now.UV, trial.UV)) return Trial::Crosses;
    return evaluate(trial) && trial.total() < now.total() ? Trial::Accepted : Trial::NoDecrease;
  };

  Iterate now, trial;
  now.UV = UV;
  evaluate(now);
  classify_triangles(frames, now.UV, now.state);
  report.energy_start = now.arap;
  AndersonAcceleration anderson(kArapAndersonDepth);
  Eigen::MatrixXd reduced_rhs, reduced_uv, target;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    if (now.total() <= negligible_energy) {
      report.converged = true;
      break;
    }
    // The Newton-like step: (L + H / 2) delta = b - L UV - grad E_barriers / 2, with H the barriers'
    // curvature (BarrierCurvature); without active terms ARAP's own global step (one solve).
    std::vector<double> rhs = now.rhs;
    for (size_t k = 0; k < rhs.size(); ++k) rhs[k] -= 0.5 * now.gradient[k];
    local_step.reduce(rhs, now.UV, reduced_rhs);
    reduced_uv.resize(reduced_rhs.rows(), 2);
    for (Eigen::Index r = 0; r < reduced_uv.rows(); ++r) reduced_uv.row(r) = now.UV.row(laplacian.vertex_of_row[r]);
    reduced_rhs -= laplacian.matrix * reduced_uv;
    std::vector<BarrierCurvature> terms;
    barrier.add_curvatures(now.UV, terms);
    fold_barrier.add_curvatures(now.UV, terms);
    reduced_uv += solve_step(laplacian, factor, terms, reduced_rhs, report.conjugate_gradients);
    local_step.expand(reduced_uv, now.UV, target);

    const double previous = now.total();
    bool moved = false;
    if (accelerate) {
      trial.UV = anderson.mix(Eigen::Map<const Eigen::VectorXd>(now.UV.data(), now.UV.size()),
                              Eigen::Map<const Eigen::VectorXd>(target.data(), target.size()))
                     .reshaped(now.UV.rows(), 2);
      moved = judge(now, trial) == Trial::Accepted;
      if (!moved) anderson.reset();
    }
    if (!moved) {
      const Eigen::MatrixXd full_step = target - now.UV;
      int halvings = 0;
      while (true) {
        trial.UV = now.UV + std::ldexp(1.0, -halvings) * full_step;
        moved = judge(now, trial) == Trial::Accepted;
        if (moved || halvings == kMostHalvings) break;
        ++halvings;
      }
      if (moved && halvings > 0) ++report.shortened_steps;
    }
    if (!moved) {
      report.stalled = true;
      break;
    }
    std::swap(now, trial);
    ++report.iterations;
    if (previous - now.total() <= relative_energy_tolerance * previous) {
      report.converged = true;
      break;
    }
  }
  UV = now.UV;
  report.energy_final = now.arap;
  report.barrier_final = now.barrier;
  report.active_pairs_final = barrier.active_pairs(UV);
  return report;
}

}  // namespace lastcut
