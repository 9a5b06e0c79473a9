#pragma once
// The outline filter of injective ARAP: a step of the map is allowed only if the flattened outline stays a
// simple polygon with a clearance between its non-adjacent edges.
//
// J. Smith, S. Schaefer, "Bijective Parameterization with Free Boundaries", ACM TOG 34(4) (SIGGRAPH 2015):
// a line search whose step is cut before a boundary vertex reaches a boundary edge keeps a free-boundary
// parameterization bijective; M. Rabinovich, R. Poranne, D. Panozzo, O. Sorkine-Hornung, "Scalable
// Locally Injective Mappings", ACM TOG 36(2), 2017, filter their steps the same way. Here the step is
// found by halving (arap_iterations.hpp) and each trial is tested at its end point only: a map whose
// triangles are all positively oriented and whose outline is a simple closed curve is injective on a disk,
// whatever path led to it, so the end-point test suffices for the iterate to be a bijection onto its image.
// Broad phase: engine/core/near_edge_pairs.hpp, over the edges' boxes grown by half the clearance.
#include <Eigen/Core>
#include <vector>

namespace lastcut {

class OutlineClearance {
 public:
  // loop: the boundary loop's vertex indices in order (>= 3); clearance_mm >= 0.
  OutlineClearance(std::vector<int> loop, double clearance_mm);

  // True when two edges of the loop that share no vertex touch or cross under UV (#V x 2, mm).
  bool crosses(const Eigen::MatrixXd& UV) const;

  // True when, moving from `current` to `trial` (both #V x 2, mm), no two edges that share no vertex come
  // closer than the clearance if they were not closer in `current`: pairs at least the clearance apart stay
  // so, pairs already closer may narrow by at most half their gap per step and never touch. With a simple
  // `current` outline the trial outline is then simple too.
  bool keeps_clear(const Eigen::MatrixXd& current, const Eigen::MatrixXd& trial) const;

  // Smallest distance (mm) between two edges at least `loop_separation` edges apart along the loop
  // (>= 1: 1 means sharing no vertex), 0 when two cross. Brute force over pairs: for tests and reports.
  double smallest_gap_mm(const Eigen::MatrixXd& UV, int loop_separation) const;

  double clearance_mm() const { return clearance_mm_; }
  const std::vector<int>& loop() const { return loop_; }

 private:
  // Calls pair(i, j) for every pair of edges i < j sharing no vertex whose boxes grown by `reach_mm` meet
  // under UV, until it returns false; returns false if it was stopped.
  template <typename Pair>
  bool for_each_near_pair(const Eigen::MatrixXd& UV, double reach_mm, Pair pair) const;

  std::vector<int> loop_;
  double clearance_mm_;
};

// Distance (mm) between the closed segments a-b and c-d; 0 when they touch.
double segment_distance_mm(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                           const Eigen::Vector2d& d);

}  // namespace lastcut
