// Anderson acceleration (Anderson 1965; Peng et al. 2018); see anderson_acceleration.hpp.
#include "engine/flatten/anderson_acceleration.hpp"

#include <Eigen/Cholesky>

namespace lastcut {

AndersonAcceleration::AndersonAcceleration(int depth) : depth_(depth) {}

void AndersonAcceleration::reset() {
  stored_ = 0;
  next_ = 0;
  has_previous_ = false;
}

Eigen::VectorXd AndersonAcceleration::mix(const Eigen::Ref<const Eigen::VectorXd>& x,
                                          const Eigen::Ref<const Eigen::VectorXd>& g) {
  const Eigen::Index n = x.size();
  if (dF_.rows() != n) {
    dF_.resize(n, depth_);
    dG_.resize(n, depth_);
    gram_.resize(depth_, depth_);
    reset();
  }
  Eigen::VectorXd f = g - x;
  if (has_previous_) {
    dF_.col(next_) = f - previous_f_;
    dG_.col(next_) = g - previous_g_;
    if (stored_ < depth_) ++stored_;
    // The Gram matrix dF^T dF changes only in the new column's row and column: depth dot products
    // instead of depth^2 per step (the history is long: 2 #V).
    for (int j = 0; j < stored_; ++j) gram_(next_, j) = gram_(j, next_) = dF_.col(j).dot(dF_.col(next_));
    next_ = (next_ + 1) % depth_;
  }
  previous_f_ = f;
  previous_g_ = g;
  has_previous_ = true;
  if (stored_ == 0) return g;

  // Small least-squares problem by its normal equations, lightly regularised: the columns of dF become
  // nearly dependent as the iteration converges.
  Eigen::MatrixXd normal = gram_.topLeftCorner(stored_, stored_);
  normal.diagonal().array() += 1e-12 * normal.trace() + 1e-300;
  const Eigen::VectorXd theta = normal.ldlt().solve(dF_.leftCols(stored_).transpose() * f);
  return g - dG_.leftCols(stored_) * theta;
}

}  // namespace lastcut
