// ARAP local/global iterations (Liu et al. 2008); see arap_iterations.hpp.
#include "engine/flatten/arap_iterations.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "engine/flatten/anderson_acceleration.hpp"

namespace lastcut {
namespace {

// A triangle is collapsed when its UV area is below kCollapsedAreaFraction of its 3D area (flipped ones
// included). Guarding against collapse rather than only against flipping keeps guarded steps from squashing
// a triangle to a sliver just short of flipping, which would be as useless in a mold as a flip.
constexpr double kCollapsedAreaFraction = 0.05;

enum TriangleState : char { kHealthy = 0, kCollapsed = 1, kFlipped = 2 };

void classify_triangles(const TriangleFrames& frames, const Eigen::MatrixXd& UV, std::vector<char>& state) {
  const double* u = UV.col(0).data();
  const double* v = UV.col(1).data();
  state.resize(frames.triangles.size());
  for (size_t f = 0; f < frames.triangles.size(); ++f) {
    const auto& t = frames.triangles[f];
    const double ax = u[t[1]] - u[t[0]], ay = v[t[1]] - v[t[0]];
    const double bx = u[t[2]] - u[t[0]], by = v[t[2]] - v[t[0]];
    const double twice_area = ax * by - ay * bx;
    state[f] = twice_area <= 0.0 ? kFlipped
               : twice_area <= 2.0 * kCollapsedAreaFraction * frames.area_mm2(f) ? kCollapsed
                                                                                   : kHealthy;
  }
}

// True when no triangle got worse (healthy -> collapsed or flipped, collapsed -> flipped).
bool no_triangle_worse(const std::vector<char>& before, const std::vector<char>& after) {
  for (size_t f = 0; f < before.size(); ++f) {
    if (after[f] > before[f]) return false;
  }
  return true;
}

// History length of Anderson acceleration; Peng et al. 2018 find 5-6 a good default for ARAP.
constexpr int kAndersonDepth = 5;

// Local step: best rotation per triangle for the current map, the global step's right-hand side
// (interleaved u, v per vertex) and the ARAP energy of the current map.
double local_step(const TriangleFrames& frames, const Eigen::MatrixXd& UV, double constant_energy,
                  std::vector<double>& rhs) {
  std::fill(rhs.begin(), rhs.end(), 0.0);
  const double* u = UV.col(0).data();
  const double* v = UV.col(1).data();
  const double* weights = frames.half_weight.data();
  const double* edges = frames.edge_local_mm.data();
  double energy = constant_energy;
  const size_t face_count = frames.triangles.size();
  for (size_t f = 0; f < face_count; ++f) {
    const auto& t = frames.triangles[f];
    const double* w = weights + 3 * f;
    const double* e = edges + 6 * f;
    // Edge k runs from t[k+1] to t[k+2].
    const double du[3] = {u[t[2]] - u[t[1]], u[t[0]] - u[t[2]], u[t[1]] - u[t[0]]};
    const double dv[3] = {v[t[2]] - v[t[1]], v[t[0]] - v[t[2]], v[t[1]] - v[t[0]]};
    double a = 0.0, b = 0.0, squared = 0.0;
    for (int k = 0; k < 3; ++k) {
      a += w[k] * (du[k] * e[2 * k] + dv[k] * e[2 * k + 1]);
      b += w[k] * (dv[k] * e[2 * k] - du[k] * e[2 * k + 1]);
      squared += w[k] * (du[k] * du[k] + dv[k] * dv[k]);
    }
    // Closest rotation [c -s; s c] to S (closest_rotation2x2, inlined: this loop is the hot path).
    const double norm = std::sqrt(a * a + b * b);
    const double c = norm > 0.0 ? a / norm : 1.0;
    const double s = norm > 0.0 ? b / norm : 0.0;
    energy += squared - 2.0 * norm;
    for (int k = 0; k < 3; ++k) {
      const double rx = w[k] * (c * e[2 * k] - s * e[2 * k + 1]);
      const double ry = w[k] * (s * e[2 * k] + c * e[2 * k + 1]);
      const int to = t[(k + 2) % 3], from = t[(k + 1) % 3];
      rhs[2 * to] += rx;
      rhs[2 * to + 1] += ry;
      rhs[2 * from] -= rx;
      rhs[2 * from + 1] -= ry;
    }
  }
  return std::max(energy, 0.0);
}

}  // namespace

ArapIterationReport run_arap_iterations(const TriangleFrames& frames, const ReducedLaplacian& laplacian,
                                        const SparseCholesky& factor, Eigen::MatrixXd& UV, int max_iterations,
                                        double relative_energy_tolerance, bool flip_guard, bool accelerate) {
  ArapIterationReport report;
  const int vertex_count = static_cast<int>(UV.rows());
  const int pinned = laplacian.pinned;

  double constant_energy = 0.0;  // sum w |x_j - x_i|^2, the energy of collapsing the map to a point
  std::vector<std::pair<int, double>> pinned_coupling;  // (row, w): L_{row,pinned} = -w
  for (size_t f = 0; f < frames.triangles.size(); ++f) {
    const auto& t = frames.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const double w = frames.half_weight[3 * f + k];
      const double ex = frames.edge_local_mm[6 * f + 2 * k], ey = frames.edge_local_mm[6 * f + 2 * k + 1];
      constant_energy += w * (ex * ex + ey * ey);
      const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      if (a == pinned) pinned_coupling.emplace_back(laplacian.row_of_vertex[b], w);
      if (b == pinned) pinned_coupling.emplace_back(laplacian.row_of_vertex[a], w);
    }
  }
  // An isometric map reaches energy 0: stop once the energy is at rounding level of the problem's scale.
  const double negligible_energy = 1e-13 * constant_energy;

  std::vector<double> rhs(2 * static_cast<size_t>(vertex_count));
  Eigen::MatrixXd reduced_rhs(laplacian.matrix.rows(), 2);
  std::vector<double> spare_rhs(rhs.size());
  Eigen::MatrixXd candidate(UV.rows(), 2), accelerated(UV.rows(), 2);
  AndersonAcceleration anderson(kAndersonDepth);
  std::vector<char> state_now, state_candidate;
  if (flip_guard) classify_triangles(frames, UV, state_now);

  double energy = local_step(frames, UV, constant_energy, rhs);
  report.energy_start = energy;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    if (energy <= negligible_energy) {
      report.converged = true;
      break;
    }
    for (Eigen::Index r = 0; r < reduced_rhs.rows(); ++r) {
      const int v = laplacian.vertex_of_row[r];
      reduced_rhs(r, 0) = rhs[2 * v];
      reduced_rhs(r, 1) = rhs[2 * v + 1];
    }
    for (const auto& [row, w] : pinned_coupling) {
      reduced_rhs(row, 0) += w * UV(pinned, 0);
      reduced_rhs(row, 1) += w * UV(pinned, 1);
    }
    const Eigen::MatrixXd solution = factor.solve(reduced_rhs);
    candidate.row(pinned) = UV.row(pinned);
    for (Eigen::Index r = 0; r < solution.rows(); ++r) candidate.row(laplacian.vertex_of_row[r]) = solution.row(r);

    const double previous = energy;
    if (flip_guard) {
      double step = 1.0;
      classify_triangles(frames, candidate, state_candidate);
      bool acceptable = no_triangle_worse(state_now, state_candidate);
      while (!acceptable && step > 1.0 / 1024.0) {
        step *= 0.5;
        candidate = UV + 0.5 * (candidate - UV);
        classify_triangles(frames, candidate, state_candidate);
        acceptable = no_triangle_worse(state_now, state_candidate);
      }
      if (!acceptable) {
        report.stalled_on_flips = true;
        break;
      }
      if (step < 1.0) ++report.shortened_steps;
      state_now.swap(state_candidate);
      UV.swap(candidate);
      energy = local_step(frames, UV, constant_energy, rhs);
    } else if (!accelerate) {
      UV.swap(candidate);
      energy = local_step(frames, UV, constant_energy, rhs);
    } else {
      // Anderson-accelerated point, kept only if it lowers the energy more than the plain step is
      // guaranteed to (Peng et al. 2018); otherwise the plain step and a fresh history.
      accelerated = anderson.mix(Eigen::Map<const Eigen::VectorXd>(UV.data(), UV.size()),
                                 Eigen::Map<const Eigen::VectorXd>(candidate.data(), candidate.size()))
                        .reshaped(UV.rows(), 2);
      const double accelerated_energy = local_step(frames, accelerated, constant_energy, spare_rhs);
      if (accelerated_energy < previous) {
        UV.swap(accelerated);
        rhs.swap(spare_rhs);
        energy = accelerated_energy;
      } else {
        anderson.reset();
        ++report.rejected_accelerations;
        UV.swap(candidate);
        energy = local_step(frames, UV, constant_energy, rhs);
      }
    }
    ++report.iterations;
    if (previous - energy <= relative_energy_tolerance * previous) {
      report.converged = true;
      break;
    }
  }
  report.energy_final = energy;
  return report;
}

}  // namespace lastcut
