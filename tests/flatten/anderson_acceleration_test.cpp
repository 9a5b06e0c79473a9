// Anderson acceleration (anderson_acceleration.hpp) against an independent textbook implementation that
// recomputes the least-squares problem from the whole history each step, and on a linear fixed-point map
// whose solution is known in closed form.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>
#include <deque>

#include "engine/flatten/anderson_acceleration.hpp"

namespace lastcut {
namespace {

// G(x) = M x + b with M diagonal, eigenvalues spread over [0.3, 0.97]: a contraction with fixed point
// x* = b / (1 - m) per entry.
struct LinearMap {
  Eigen::VectorXd m, b;
  Eigen::VectorXd operator()(const Eigen::VectorXd& x) const { return m.cwiseProduct(x) + b; }
  Eigen::VectorXd fixed_point() const { return b.cwiseQuotient(Eigen::VectorXd::Ones(m.size()) - m); }
};

LinearMap spread_map(int n) {
  LinearMap map;
  map.m = Eigen::VectorXd::LinSpaced(n, 0.3, 0.97);
  map.b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  return map;
}

// Textbook Anderson(depth): the differences of the last depth steps, theta from a fresh QR each step.
Eigen::VectorXd reference_mix(std::deque<Eigen::VectorXd>& xs, std::deque<Eigen::VectorXd>& gs, int depth) {
  while (static_cast<int>(xs.size()) > depth + 1) {
    xs.pop_front();
    gs.pop_front();
  }
  const int stored = static_cast<int>(xs.size()) - 1;
  if (stored == 0) return gs.back();
  const Eigen::Index n = xs.back().size();
  Eigen::MatrixXd dF(n, stored), dG(n, stored);
  for (int j = 0; j < stored; ++j) {
    dF.col(j) = (gs[j + 1] - xs[j + 1]) - (gs[j] - xs[j]);
    dG.col(j) = gs[j + 1] - gs[j];
  }
  const Eigen::VectorXd f = gs.back() - xs.back();
  const Eigen::VectorXd theta = dF.colPivHouseholderQr().solve(f);
  return gs.back() - dG * theta;
}

TEST(AndersonAcceleration, MatchesTheTextbookMethodAcrossTheHistoryWrap) {
  const LinearMap map = spread_map(40);
  constexpr int kDepth = 5;
  AndersonAcceleration anderson(kDepth);
  std::deque<Eigen::VectorXd> xs, gs;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(40), x_ref = x;
  // 12 steps: the ring of 5 differences wraps twice. The tolerance allows for the normal equations
  // (condition squared) against QR; a wrong or stale Gram entry changes the step at order 1.
  for (int step = 0; step < 12; ++step) {
    x = anderson.mix(x, map(x));
    xs.push_back(x_ref);
    gs.push_back(map(x_ref));
    x_ref = reference_mix(xs, gs, kDepth);
    ASSERT_LT((x - x_ref).norm(), 1e-6 * x_ref.norm()) << "step " << step;
  }
}

TEST(AndersonAcceleration, ConvergesFarFasterThanThePlainIteration) {
  const LinearMap map = spread_map(40);
  const Eigen::VectorXd exact = map.fixed_point();
  AndersonAcceleration anderson(5);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(40), plain = x;
  for (int step = 0; step < 40; ++step) {
    x = anderson.mix(x, map(x));
    plain = map(plain);
  }
  // The slowest mode of the plain iteration is still 0.97^40 ~ 0.3 of its start error away.
  EXPECT_GT((plain - exact).norm(), 0.1 * exact.norm());
  std::printf("error after 40 steps: plain %.3g, Anderson %.3g\n", (plain - exact).norm(), (x - exact).norm());
  EXPECT_LT((x - exact).norm(), 1e-4 * (plain - exact).norm());
  anderson.reset();  // after a reset the first mix is the plain step
  EXPECT_EQ(anderson.mix(plain, map(plain)), map(plain));
}

}  // namespace
}  // namespace lastcut
