// ARAP local/global iterations (Liu et al. 2008); see arap_iterations.hpp.
#include "engine/flatten/arap_iterations.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/flatten/anderson_acceleration.hpp"
#include "engine/flatten/arap_local_step.hpp"

namespace lastcut {
ArapIterationReport run_arap_iterations(const TriangleFrames& frames, const ReducedLaplacian& laplacian,
                                        const SparseCholesky& factor, Eigen::MatrixXd& UV, int max_iterations,
                                        double relative_energy_tolerance, bool flip_guard, bool accelerate,
                                        const OutlineClearance* outline, int give_up_after_crossing) {
  if (flip_guard && outline != nullptr)
    throw EngineError("flatten: an outline is watched by unguarded ARAP only (bijective ARAP keeps it clear)");
  ArapIterationReport report;
  const int vertex_count = static_cast<int>(UV.rows());

  const ArapLocalStep local_step(frames, laplacian);
  // An isometric map reaches energy 0: stop once the energy is at rounding level of the problem's scale.
  const double negligible_energy = 1e-13 * local_step.constant_energy();

  std::vector<double> rhs(2 * static_cast<size_t>(vertex_count));
  Eigen::MatrixXd reduced_rhs;
  std::vector<double> spare_rhs(rhs.size());
  Eigen::MatrixXd candidate(UV.rows(), 2), accelerated(UV.rows(), 2);
  AndersonAcceleration anderson(kArapAndersonDepth);
  std::vector<char> state_now, state_candidate;
  if (flip_guard) classify_triangles(frames, UV, state_now);

  const bool stop_before_fold = !flip_guard && outline != nullptr && give_up_after_crossing <= 0;
  const bool watch_crossing = !flip_guard && outline != nullptr && give_up_after_crossing > 0;
  int crossed_in_a_row = 0;
  Eigen::MatrixXd last_injective;
  if (stop_before_fold) last_injective = UV;
  double energy = local_step.run(UV, rhs);
  report.energy_start = energy;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    if (energy <= negligible_energy) {
      report.converged = true;
      break;
    }
    local_step.reduce(rhs, UV, reduced_rhs);
    local_step.expand(factor.solve(reduced_rhs), UV, candidate);

    const double previous = energy;
    if (flip_guard) {
      double step = 1.0;
      const auto acceptable_step = [&] {
        classify_triangles(frames, candidate, state_candidate);
        return no_triangle_worse(state_now, state_candidate);
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
      energy = local_step.run(UV, rhs);
    } else if (!accelerate) {
      UV.swap(candidate);
      energy = local_step.run(UV, rhs);
    } else {
      // Anderson-accelerated point, kept only if it lowers the energy more than the plain step is
      // guaranteed to (Peng et al. 2018); otherwise the plain step and a fresh history.
      accelerated = anderson.mix(Eigen::Map<const Eigen::VectorXd>(UV.data(), UV.size()),
                                 Eigen::Map<const Eigen::VectorXd>(candidate.data(), candidate.size()))
                        .reshaped(UV.rows(), 2);
      const double accelerated_energy = local_step.run(accelerated, spare_rhs);
      if (accelerated_energy < previous) {
        UV.swap(accelerated);
        rhs.swap(spare_rhs);
        energy = accelerated_energy;
      } else {
        anderson.reset();
        ++report.rejected_accelerations;
        UV.swap(candidate);
        energy = local_step.run(UV, rhs);
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
