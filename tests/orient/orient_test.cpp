// Orientation of scans in any pose: generated lasts of several sizes, both sides, with noise and
// holes, must come back in the generator's canonical frame (up to the 3 degree tilt of its top
// cut, which the orientation takes as level) with the right side, the same every run.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <iostream>
#include <numbers>

#include "engine/lastgen/generate_last.hpp"
#include "engine/orient/orient_last.hpp"
#include "tests/support/last_cases.hpp"

namespace lastcut {
namespace {

using test::LastCase;

TriMesh transformed(const TriMesh& mesh, const Eigen::Affine3d& pose) {
  TriMesh result = mesh;
  result.V = (mesh.V * pose.linear().transpose()).rowwise() + pose.translation().transpose();
  return result;
}

class OrientGeneratedLast : public testing::TestWithParam<LastCase> {};

TEST_P(OrientGeneratedLast, RecoversTheCanonicalFrameAndTheSide) {
  const LastCase c = GetParam();
  LastParams params = LastParams::for_eu_size(c.eu_size, c.side);
  params.target_triangles = 15000;
  params.noise_mm = 0.2;
  params.holes = 3;
  params.random_pose = true;
  params.seed = c.seed;
  const GeneratedLast scan = generate_last(params);
  const OrientedLast last = orient_last(scan.mesh);

  EXPECT_EQ(last.side, c.side);
  const Eigen::Matrix3d rotation = last.scan_to_canonical.linear();
  EXPECT_NEAR(rotation.determinant(), 1.0, 1e-9);
  EXPECT_LT((rotation * rotation.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-9);
  const Eigen::Matrix3d truth = scan.canonical_to_scan.linear().transpose();  // scan -> canonical
  const double error_deg = Eigen::AngleAxisd(rotation * truth.transpose()).angle() * 180.0 / std::numbers::pi;
  std::cout << "rotation error " << error_deg << " deg\n";
  EXPECT_LT(error_deg, 5.0);
  // The generator's frame, up to that rotation: toe +X (heel to toe), up +Z.
  EXPECT_GT((rotation * truth.transpose())(0, 0), std::cos(5.0 * std::numbers::pi / 180.0));
  EXPECT_GT((rotation * truth.transpose())(2, 2), std::cos(5.0 * std::numbers::pi / 180.0));

  // The transform and the mesh agree; sole on z = 0, heel at x = 0, length preserved.
  const TriMesh again = transformed(scan.mesh, last.scan_to_canonical);
  EXPECT_LT((again.V - last.mesh.V).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_NEAR(last.mesh.V.col(2).minCoeff(), 0.0, 1e-9);
  EXPECT_NEAR(last.mesh.V.col(0).minCoeff(), 0.0, 1e-9);
  EXPECT_NEAR(last.mesh.V.col(0).maxCoeff(), params.length_mm, 0.03 * params.length_mm);
  EXPECT_EQ(last.mesh.F, scan.mesh.F);
  EXPECT_GE(last.notes.size(), 3u);
}

INSTANTIATE_TEST_SUITE_P(Sizes, OrientGeneratedLast,
                         testing::Values(LastCase{35, FootSide::Left, 31}, LastCase{37, FootSide::Right, 32},
                                         LastCase{41, FootSide::Left, 33}, LastCase{44, FootSide::Right, 34},
                                         LastCase{47, FootSide::Left, 35}, LastCase{47, FootSide::Right, 36}),
                         test::last_case_name);

TEST(OrientGeneratedLast, IsDeterministic) {
  LastParams params = LastParams::for_eu_size(42, FootSide::Right);
  params.target_triangles = 8000;
  params.noise_mm = 0.2;
  params.random_pose = true;
  const TriMesh scan = generate_last(params).mesh;
  const OrientedLast first = orient_last(scan), second = orient_last(scan);
  EXPECT_EQ(first.mesh.V, second.mesh.V);
  EXPECT_TRUE(first.scan_to_canonical.isApprox(second.scan_to_canonical, 0.0));
  EXPECT_EQ(first.notes, second.notes);
}

}  // namespace
}  // namespace lastcut
