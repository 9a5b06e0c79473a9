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

// Per corner j of each triangle, the constant 2-vector c_j = w_(j+1) e_(j+1) - w_(j+2) e_(j+2) (6 #F, mm):
// the cross-covariance is sum_j (u_j, v_j) against c_j and corner j's share of the right-hand side is R c_j,
// so the local step reads and writes each vertex once per triangle instead of once per edge end.
std::vector<double> corner_vectors(const TriangleFrames& frames) {
  const size_t face_count = frames.triangles.size();
  std::vector<double> corner(6 * face_count);
  for (size_t f = 0; f < face_count; ++f) {
    const double* w = &frames.half_weight[3 * f];
    const double* e = &frames.edge_local_mm[6 * f];
    for (int j = 0; j < 3; ++j) {
      const int plus = (j + 1) % 3, minus = (j + 2) % 3;
      corner[6 * f + 2 * j] = w[plus] * e[2 * plus] - w[minus] * e[2 * minus];
      corner[6 * f + 2 * j + 1] = w[plus] * e[2 * plus + 1] - w[minus] * e[2 * minus + 1];
    }
  }
  return corner;
}

// Local step: best rotation per triangle for the current map, the global step's right-hand side
// (interleaved u, v per vertex) and the ARAP energy of the current map. corner: corner_vectors(frames).
double local_step(const TriangleFrames& frames, const std::vector<double>& corner, const Eigen::MatrixXd& UV,
                  double constant_energy, std::vector<double>& rhs_vector) {
  std::fill(rhs_vector.begin(), rhs_vector.end(), 0.0);
  double* rhs = rhs_vector.data();
  const double* u = UV.col(0).data();
  const double* v = UV.col(1).data();
  const double* weights = frames.half_weight.data();
  const double* corners = corner.data();
  double energy = constant_energy;
  const size_t face_count = frames.triangles.size();
  for (size_t f = 0; f < face_count; ++f) {
    const int i0 = frames.triangles[f][0], i1 = frames.triangles[f][1], i2 = frames.triangles[f][2];
    const double u0 = u[i0], u1 = u[i1], u2 = u[i2], v0 = v[i0], v1 = v[i1], v2 = v[i2];
    const double* w = weights + 3 * f;
    const double* c = corners + 6 * f;
    const double a = u0 * c[0] + v0 * c[1] + u1 * c[2] + v1 * c[3] + u2 * c[4] + v2 * c[5];
    const double b = v0 * c[0] - u0 * c[1] + v1 * c[2] - u1 * c[3] + v2 * c[4] - u2 * c[5];
    // Edge k runs from t[k+1] to t[k+2].
    const double du0 = u2 - u1, du1 = u0 - u2, du2 = u1 - u0;
    const double dv0 = v2 - v1, dv1 = v0 - v2, dv2 = v1 - v0;
    const double squared = w[0] * (du0 * du0 + dv0 * dv0) + w[1] * (du1 * du1 + dv1 * dv1) +
                           w[2] * (du2 * du2 + dv2 * dv2);
    // Closest rotation [cs -sn; sn cs] to S (closest_rotation2x2, inlined: this loop is the hot path).
    const double norm = std::sqrt(a * a + b * b);
    const double cs = norm > 0.0 ? a / norm : 1.0;
    const double sn = norm > 0.0 ? b / norm : 0.0;
    energy += squared - 2.0 * norm;
    rhs[2 * i0] += cs * c[0] - sn * c[1];
    rhs[2 * i0 + 1] += sn * c[0] + cs * c[1];
    rhs[2 * i1] += cs * c[2] - sn * c[3];
    rhs[2 * i1 + 1] += sn * c[2] + cs * c[3];
    rhs[2 * i2] += cs * c[4] - sn * c[5];
    rhs[2 * i2 + 1] += sn * c[4] + cs * c[5];
  }
  return std::max(energy, 0.0);
}

}  // namespace

ArapIterationReport run_arap_iterations(const TriangleFrames& frames, const ReducedLaplacian& laplacian,
                                        const SparseCholesky& factor, Eigen::MatrixXd& UV, int max_iterations,
                                        double relative_energy_tolerance, bool flip_guard, bool accelerate,
                                        const OutlineClearance* outline, int give_up_after_crossing) {
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

  const std::vector<double> corner = corner_vectors(frames);
  std::vector<double> rhs(2 * static_cast<size_t>(vertex_count));
  Eigen::MatrixXd reduced_rhs(laplacian.matrix.rows(), 2);
  std::vector<double> spare_rhs(rhs.size());
  Eigen::MatrixXd candidate(UV.rows(), 2), accelerated(UV.rows(), 2);
  AndersonAcceleration anderson(kAndersonDepth);
  std::vector<char> state_now, state_candidate;
  if (flip_guard) classify_triangles(frames, UV, state_now);

  const bool stop_before_fold = !flip_guard && outline != nullptr && give_up_after_crossing <= 0;
  const bool watch_crossing = !flip_guard && outline != nullptr && give_up_after_crossing > 0;
  int crossed_in_a_row = 0;
  Eigen::MatrixXd last_injective;
  if (stop_before_fold) last_injective = UV;
  double energy = local_step(frames, corner, UV, constant_energy, rhs);
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
    // The Anderson-mixed point of UV and the plain step into `accelerated`, its energy (right-hand side
    // into spare_rhs).
    const auto mix_accelerated = [&] {
      accelerated = anderson.mix(Eigen::Map<const Eigen::VectorXd>(UV.data(), UV.size()),
                                 Eigen::Map<const Eigen::VectorXd>(candidate.data(), candidate.size()))
                        .reshaped(UV.rows(), 2);
      return local_step(frames, corner, accelerated, constant_energy, spare_rhs);
    };
    const auto take_accelerated = [&](double accelerated_energy) {
      UV.swap(accelerated);
      rhs.swap(spare_rhs);
      energy = accelerated_energy;
    };
    bool took_accelerated = false;
    if (flip_guard && outline != nullptr && accelerate) {
      // Injective mode: an Anderson point is kept only if it lowers the energy, folds nothing and keeps
      // the outline clear; otherwise the filtered plain step below.
      const double accelerated_energy = mix_accelerated();
      if (accelerated_energy < previous) {
        classify_triangles(frames, accelerated, state_candidate);
        if (no_triangle_worse(state_now, state_candidate) && outline->keeps_clear(UV, accelerated)) {
          state_now.swap(state_candidate);
          take_accelerated(accelerated_energy);
          took_accelerated = true;
        }
      }
      if (!took_accelerated) {
        anderson.reset();
        ++report.rejected_accelerations;
      }
    }
    if (took_accelerated) {
      // Kept above: on to the convergence test.
    } else if (flip_guard) {
      double step = 1.0;
      const auto acceptable_step = [&] {
        classify_triangles(frames, candidate, state_candidate);
        return no_triangle_worse(state_now, state_candidate) &&
               (outline == nullptr || outline->keeps_clear(UV, candidate));
      };
      bool acceptable = acceptable_step();
      while (!acceptable && step > 1.0 / 1024.0) {
        step *= 0.5;
        candidate = UV + 0.5 * (candidate - UV);
        acceptable = acceptable_step();
      }
      if (!acceptable) {
        report.stalled_on_flips = true;
        break;
      }
      if (step < 1.0) ++report.shortened_steps;
      state_now.swap(state_candidate);
      UV.swap(candidate);
      energy = local_step(frames, corner, UV, constant_energy, rhs);
    } else if (!accelerate) {
      UV.swap(candidate);
      energy = local_step(frames, corner, UV, constant_energy, rhs);
    } else {
      // Anderson-accelerated point, kept only if it lowers the energy more than the plain step is
      // guaranteed to (Peng et al. 2018); otherwise the plain step and a fresh history.
      const double accelerated_energy = mix_accelerated();
      if (accelerated_energy < previous) {
        take_accelerated(accelerated_energy);
      } else {
        anderson.reset();
        ++report.rejected_accelerations;
        UV.swap(candidate);
        energy = local_step(frames, corner, UV, constant_energy, rhs);
      }
    }
    ++report.iterations;
    if (watch_crossing) {
      crossed_in_a_row = outline->crosses(UV) ? crossed_in_a_row + 1 : 0;
      if (crossed_in_a_row >= give_up_after_crossing) {
        report.gave_up_crossed = true;
        break;
      }
    }
    if (stop_before_fold) {
      // Unguarded with an outline: stop at the first iterate that folds or crosses, keeping the one before.
      classify_triangles(frames, UV, state_candidate);
      const bool flipped = std::find(state_candidate.begin(), state_candidate.end(), kFlipped) != state_candidate.end();
      if (flipped || outline->crosses(UV)) {
        UV = last_injective;
        break;
      }
      last_injective = UV;
    }
    if (previous - energy <= relative_energy_tolerance * previous) {
      report.converged = true;
      break;
    }
  }
  report.energy_final = energy;
  return report;
}

}  // namespace lastcut
