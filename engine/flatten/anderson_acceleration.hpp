#pragma once
// Anderson acceleration of a fixed-point iteration x <- G(x).
//
// D. G. Anderson, "Iterative procedures for nonlinear integral equations", J. ACM 12(4), 1965; applied to
// local/global solvers (with an energy safeguard the caller applies) by Y. Peng, B. Deng, J. Zhang, F. Geng,
// W. Qin, L. Liu, "Anderson Acceleration for Geometry Optimization and Physics Simulation", ACM TOG 37(4),
// SIGGRAPH 2018. With residuals f = G(x) - x, the next point is G(x_k) - dG theta where theta minimises
// || f_k - dF theta || over the last `depth` differences dF, dG.
#include <Eigen/Core>

namespace lastcut {

// History length for ARAP's iterations; Peng et al. 2018 find 5-6 a good default for ARAP.
constexpr int kArapAndersonDepth = 5;

class AndersonAcceleration {
 public:
  explicit AndersonAcceleration(int depth);
  // x: the current iterate, g = G(x); both the same length every call. Returns the accelerated point
  // (g itself on the first call after construction or reset()).
  Eigen::VectorXd mix(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& g);
  // Forget the history (after the caller rejected an accelerated point).
  void reset();

 private:
  int depth_;
  int stored_ = 0;  // differences in the history
  int next_ = 0;    // column the next difference goes to
  bool has_previous_ = false;
  Eigen::MatrixXd dF_, dG_;
  Eigen::MatrixXd gram_;  // depth x depth: dF^T dF of the stored columns
  Eigen::VectorXd previous_f_, previous_g_;
};

}  // namespace lastcut
