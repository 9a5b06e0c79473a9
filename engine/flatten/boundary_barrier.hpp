#pragma once
// The boundary barrier of bijective ARAP: an energy that grows without bound as a vertex of the mold's
// outline comes near an outline edge it is not next to, so the descent itself keeps the outline from
// closing on itself instead of only a line search cutting the steps that would.
//
// J. Smith, S. Schaefer, "Bijective Parameterization with Free Boundaries", ACM TOG 34(4), 2015, eq. 4:
// for each outline vertex v and outline edge e with distance d(v, e) < epsilon,
//   E_B = sum lambda * (epsilon / d - 1)^2        (0 where d >= epsilon; barrier_function.hpp)
// which is smooth (its value and slope vanish at d = epsilon) and infinite at contact. Epsilon is set
// per pair: a vertex and an edge that are close along the 3D outline (a corner, a spike's two sides,
// neighbours) are that close on the surface too, so their epsilon is half their distance along the
// outline, never below least_activation_mm and never above activation_mm. Neighbours on a smooth
// outline are thus never pushed apart along it, yet the two sides of a spike cannot close.
// Broad phase: engine/core/near_edge_pairs.hpp over the edges' boxes grown by epsilon / 2.
#include <Eigen/Core>
#include <vector>

#include "engine/flatten/barrier_function.hpp"

namespace lastcut {

struct BoundaryBarrierOptions {
  double activation_mm = 1.0;        // epsilon at most: pairs farther apart than this are free
  double least_activation_mm = 0.2;  // epsilon at least (above the outline clearance, outline_clearance.hpp)
  // lambda = stiffness * epsilon^2 (mm^2, the ARAP energy's unit): holding a pair at epsilon / 2 then costs
  // about what moving one interior vertex by epsilon / 2 costs ARAP (cotangent weights sum to ~3 per vertex).
  double stiffness = 1.0;
};

class BoundaryBarrier {
 public:
  // loop: the outline's vertex ids in order (>= 3); arc_mm: its 3D edge lengths (loop.size(), edge k from
  // loop[k] to loop[k+1]).
  BoundaryBarrier(std::vector<int> loop, const std::vector<double>& arc_mm, const BoundaryBarrierOptions& options);

  // E_B of UV (#V x 2, mm; mm^2). With `gradient` (2 #V, interleaved u, v), adds dE_B/dUV to it.
  // Infinite when a vertex touches an edge it is paired with.
  double energy(const Eigen::MatrixXd& UV, std::vector<double>* gradient = nullptr) const;

  // Appends the barrier's curvature for a Newton-like step, one term per active pair: its vertices (the
  // outline vertex, the edge's two ends), the weights c = (1, -(1 - t), -t) with which they make the
  // distance's change, and d2E/dd2. sum curvature * (c . dU)^2 over both coordinates bounds the pair's
  // Gauss-Newton term from above (the distance's direction n has |n| = 1), so the same matrix serves u and v.
  void add_curvatures(const Eigen::MatrixXd& UV, std::vector<BarrierCurvature>& terms) const;

  // Vertex-edge pairs closer than their epsilon under UV (for reports).
  int active_pairs(const Eigen::MatrixXd& UV) const;

  double activation_mm() const { return epsilon_mm_; }

 private:
  template <typename Visit>
  void for_each_active_pair(const Eigen::MatrixXd& UV, Visit visit) const;

  std::vector<int> loop_;
  std::vector<double> arc_start_mm_;  // 3D arc length from loop[0] to loop[k] along the outline
  double loop_length_mm_ = 0;
  double epsilon_mm_ = 0;
  double least_epsilon_mm_ = 0;
  double stiffness_ = 0;
};

}  // namespace lastcut
