// The analytic 2x2 SVD (thesis Algorithm 1, corrected) against Eigen's JacobiSVD on 100,000 matrices of
// each kind: random regular, rank 1, nearly singular, conformal (scaled rotations), and the zero matrix.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <random>

#include "engine/flatten/svd2x2.hpp"

namespace lastcut {
namespace {

// Singular values are defined to within eps * ||A|| (Weyl), so errors are measured relative to sigma1
// (the 2-norm of A); for the zero matrix the error is absolute.
void expect_valid_svd(const Eigen::Matrix2d& A) {
  const Svd2 svd = svd2x2(A);
  const Eigen::JacobiSVD<Eigen::Matrix2d> reference(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector2d expected = reference.singularValues();
  const double scale = expected(0) > 0.0 ? expected(0) : 1.0;
  ASSERT_NEAR(svd.sigma(0), expected(0), 1e-12 * scale) << A;
  ASSERT_NEAR(svd.sigma(1), expected(1), 1e-12 * scale) << A;
  ASSERT_GE(svd.sigma(0), svd.sigma(1)) << A;
  ASSERT_GE(svd.sigma(1), 0.0) << A;
  ASSERT_LT((svd.U.transpose() * svd.U - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff(), 1e-13) << A;
  ASSERT_LT((svd.V.transpose() * svd.V - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff(), 1e-13) << A;
  const Eigen::Matrix2d rebuilt = svd.U * svd.sigma.asDiagonal() * svd.V.transpose();
  ASSERT_LT((rebuilt - A).cwiseAbs().maxCoeff(), 1e-13 * scale) << A;
}

constexpr int kCount = 100000;

TEST(Svd2x2, RandomRegularMatricesMatchJacobiSvd) {
  std::mt19937_64 rng(1);
  std::normal_distribution<double> entry(0.0, 1.0);
  std::uniform_real_distribution<double> log_scale(-6.0, 6.0);
  for (int i = 0; i < kCount; ++i) {
    Eigen::Matrix2d A;
    A << entry(rng), entry(rng), entry(rng), entry(rng);
    expect_valid_svd(A * std::pow(10.0, log_scale(rng)));
  }
}

TEST(Svd2x2, RankOneMatricesMatchJacobiSvd) {
  std::mt19937_64 rng(2);
  std::normal_distribution<double> entry(0.0, 1.0);
  for (int i = 0; i < kCount; ++i) {
    const Eigen::Vector2d a(entry(rng), entry(rng)), b(entry(rng), entry(rng));
    const Eigen::Matrix2d A = a * b.transpose();
    expect_valid_svd(A);
    EXPECT_LT(svd2x2(A).sigma(1), 1e-15 * A.norm());
  }
}

TEST(Svd2x2, SingularAndNearlySingularMatricesMatchJacobiSvd) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> entry(0.0, 1.0);
  std::uniform_real_distribution<double> log_gap(-15.0, 0.0);
  for (int i = 0; i < kCount; ++i) {
    Eigen::Matrix2d A;
    switch (i % 4) {
      case 0: A << entry(rng), 0.0, entry(rng), 0.0; break;    // a zero column
      case 1: A << 0.0, 0.0, entry(rng), entry(rng); break;    // a zero row
      case 2: {  // dependent columns
        const double x = entry(rng), y = entry(rng);
        A << x, 2.0 * x, y, 2.0 * y;
        break;
      }
      default: {  // sigma2 / sigma1 down to 1e-15
        const double angle_u = entry(rng), angle_v = entry(rng);
        Eigen::Matrix2d U, V;
        U << std::cos(angle_u), -std::sin(angle_u), std::sin(angle_u), std::cos(angle_u);
        V << std::cos(angle_v), std::sin(angle_v), std::sin(angle_v), -std::cos(angle_v);
        A = U * Eigen::Vector2d(1.0, std::pow(10.0, log_gap(rng))).asDiagonal() * V.transpose();
      }
    }
    expect_valid_svd(A);
  }
}

TEST(Svd2x2, ConformalMatricesMatchJacobiSvd) {
  // Scaled rotations and reflections: sigma1 == sigma2, where the published line 4 divides 0 by 0.
  std::mt19937_64 rng(4);
  std::normal_distribution<double> entry(0.0, 1.0);
  for (int i = 0; i < kCount; ++i) {
    const double c = entry(rng), s = entry(rng);
    Eigen::Matrix2d A;
    if (i % 2 == 0) {
      A << c, -s, s, c;
    } else {
      A << c, s, s, -c;
    }
    if (i % 3 == 0) A(0, 1) += 1e-12 * entry(rng);  // nearly conformal
    expect_valid_svd(A);
  }
}

TEST(Svd2x2, ZeroMatrixGivesZeroSingularValuesAndOrthonormalFactors) {
  expect_valid_svd(Eigen::Matrix2d::Zero());
  const Svd2 svd = svd2x2(Eigen::Matrix2d::Zero());
  EXPECT_EQ(svd.sigma(0), 0.0);
  EXPECT_EQ(svd.sigma(1), 0.0);
}

TEST(Svd2x2, PublishedExampleDiagonalAndPermutation) {
  Eigen::Matrix2d A;
  A << 3.0, 0.0, 0.0, -2.0;
  const Svd2 d = svd2x2(A);
  EXPECT_DOUBLE_EQ(d.sigma(0), 3.0);
  EXPECT_DOUBLE_EQ(d.sigma(1), 2.0);
  A << 0.0, 5.0, 4.0, 0.0;
  expect_valid_svd(A);
  EXPECT_DOUBLE_EQ(svd2x2(A).sigma(0), 5.0);
  EXPECT_DOUBLE_EQ(svd2x2(A).sigma(1), 4.0);
}

TEST(ClosestRotation2x2, EqualsSvdPolarFactorIncludingReflections) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> entry(0.0, 1.0);
  for (int i = 0; i < kCount; ++i) {
    Eigen::Matrix2d S;
    S << entry(rng), entry(rng), entry(rng), entry(rng);
    const Svd2 svd = svd2x2(S);
    const double d = (svd.U * svd.V.transpose()).determinant() < 0.0 ? -1.0 : 1.0;
    const Eigen::Matrix2d expected = svd.U * Eigen::Vector2d(1.0, d).asDiagonal() * svd.V.transpose();
    const Eigen::Matrix2d R = closest_rotation2x2(S);
    ASSERT_NEAR(R.determinant(), 1.0, 1e-14);
    // Where sigma1 - d*sigma2 is ~0 the closest rotation is not unique; skip those few.
    if (svd.sigma(0) - d * svd.sigma(1) < 1e-9 * svd.sigma(0)) continue;
    ASSERT_LT((R - expected).cwiseAbs().maxCoeff(), 1e-9) << S;
    // And no other rotation is closer: trace(R^T S) is maximal.
    const double best = (R.transpose() * S).trace();
    for (double angle = 0.0; angle < 6.28; angle += 0.5) {
      Eigen::Matrix2d Q;
      Q << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
      ASSERT_LE((Q.transpose() * S).trace(), best + 1e-12);
    }
  }
}

}  // namespace
}  // namespace lastcut
