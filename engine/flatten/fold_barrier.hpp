#pragma once
// The fold barrier of bijective ARAP: an energy that grows without bound as a triangle's area in the map
// shrinks towards zero, so that the descent keeps every triangle positive by itself instead of the flip
// guard cutting every step of the whole map where a few triangles are about to fold (jamming).
//
// C. Schüller, L. Kavan, D. Panozzo, O. Sorkine-Hornung, "Locally Injective Mappings", SGP 2013: a barrier
// on each triangle's signed area, zero above a threshold and infinite at zero, added to ARAP's energy.
// Here, per triangle with area ratio r = (area in the map) / (3D area),
//   E_F = sum mu * A_3D * (s / r - 1)^2     for r < s (0 otherwise; barrier_function.hpp),
// smooth at r = s like the boundary barrier (boundary_barrier.hpp). s = 0.2: four times the flip guard's
// collapse threshold (5 % of the 3D area, arap_local_step.hpp), so healthy triangles meet the barrier long
// before the guard; a triangle already thinner in the start map gets half its start ratio as its s (as
// Schüller et al. set the barrier from the start map), so a start that squeezes a strip (the Tutte map
// of a long spiral) is not pinned where it is.
#include <Eigen/Core>
#include <vector>

#include "engine/flatten/barrier_function.hpp"
#include "engine/flatten/cotangent_laplacian.hpp"

namespace lastcut {

class FoldBarrier {
 public:
  // frames must outlive the barrier; start: the start map (#V x 2, mm, every triangle positive).
  // activation_ratio: s above; stiffness: mu (per mm^2 of 3D area).
  FoldBarrier(const TriangleFrames& frames, const Eigen::MatrixXd& start, double activation_ratio = 0.2,
              double stiffness = 1.0);

  // E_F of UV (#V x 2, mm; mm^2); with `gradient` (2 #V, interleaved u, v) adds dE_F/dUV to it. Infinite
  // when a triangle has zero or negative area.
  double energy(const Eigen::MatrixXd& UV, std::vector<double>* gradient = nullptr) const;

  // Appends, per triangle below the threshold, two terms bounding its Gauss-Newton curvature from above
  // with the same matrix for u and v: q q^T <= 2 (q_u q_u^T + q_v q_v^T) per column.
  void add_curvatures(const Eigen::MatrixXd& UV, std::vector<BarrierCurvature>& terms) const;

 private:
  // visit(f, r, q_u[3], q_v[3]) for each triangle with r < s; q: dr/du and dr/dv at its corners.
  template <typename Visit>
  void for_each_active_triangle(const Eigen::MatrixXd& UV, Visit visit) const;

  const TriangleFrames& frames_;
  std::vector<double> activation_ratio_;  // s per triangle
  double stiffness_;
};

}  // namespace lastcut
