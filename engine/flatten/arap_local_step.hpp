#pragma once
// The parts of an ARAP iteration shared by its two schemes: plain local/global iterations
// (arap_iterations.hpp) and ARAP with a boundary barrier (barrier_arap_iterations.hpp).
// Liu et al. 2008, see arap_iterations.hpp for the energy.
//   - ArapLocalStep: the best rotation per triangle for the current map, the global step's right-hand
//     side and the ARAP energy, in one pass over the triangles (the hot loop).
//   - classify_triangles / no_triangle_worse: the flip guard's test of a step.
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "engine/flatten/cotangent_laplacian.hpp"

namespace lastcut {

class ArapLocalStep {
 public:
  // frames must outlive the step; `pinned` is the vertex the global step keeps fixed (laplacian.pinned).
  ArapLocalStep(const TriangleFrames& frames, const ReducedLaplacian& laplacian);

  // ARAP energy of UV (#V x 2, mm) with the best rotations (mm^2), and into rhs (2 #V, interleaved u, v)
  // the global step's right-hand side for those rotations.
  double run(const Eigen::MatrixXd& UV, std::vector<double>& rhs) const;

  // The global step's right-hand side (#V-1 x 2, rows of the reduced Laplacian) from rhs (2 #V) and the
  // pinned vertex's position in UV.
  void reduce(const std::vector<double>& rhs, const Eigen::MatrixXd& UV, Eigen::MatrixXd& reduced_rhs) const;

  // The solution of the reduced system written back into a #V x 2 map (the pinned vertex from UV).
  void expand(const Eigen::MatrixXd& solution, const Eigen::MatrixXd& UV, Eigen::MatrixXd& out) const;

  // sum w |x_j - x_i|^2 over the 3D edges: the energy of collapsing the map to a point (mm^2).
  double constant_energy() const { return constant_energy_; }

 private:
  const TriangleFrames& frames_;
  const ReducedLaplacian& laplacian_;
  double constant_energy_ = 0.0;
  std::vector<double> corner_;                          // 6 #F, see arap_local_step.cpp
  std::vector<std::pair<int, double>> pinned_coupling_;  // (row, w): L_{row,pinned} = -w
};

// A triangle is collapsed when its UV area is below 5 % of its 3D area (flipped ones included). Guarding
// against collapse rather than only against flipping keeps guarded steps from squashing a triangle to a
// sliver just short of flipping, which would be as useless in a mold as a flip.
enum TriangleState : char { kHealthy = 0, kCollapsed = 1, kFlipped = 2 };

// state: one TriangleState per triangle of frames under UV (#V x 2, mm).
void classify_triangles(const TriangleFrames& frames, const Eigen::MatrixXd& UV, std::vector<char>& state);

// True when no triangle got worse (healthy -> collapsed or flipped, collapsed -> flipped).
bool no_triangle_worse(const std::vector<char>& before, const std::vector<char>& after);

}  // namespace lastcut
