// Orientation of a real scanned shape in any pose (the FIND foot template) and refusal of shapes
// that are not lasts, with one readable line.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <iostream>
#include <random>

#include "engine/core/engine_error.hpp"
#include "engine/orient/orient_last.hpp"
#include "../segment/segment_test_support.hpp"

namespace lastcut {
namespace {

Eigen::Affine3d random_rigid(std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gauss;
  Eigen::Quaterniond q(gauss(random), gauss(random), gauss(random), gauss(random));
  Eigen::Affine3d pose = Eigen::Affine3d::Identity();
  pose.linear() = q.normalized().toRotationMatrix();
  pose.translation() = Eigen::Vector3d(gauss(random), gauss(random), gauss(random)) * 100.0;
  return pose;
}

TriMesh transformed(const TriMesh& mesh, const Eigen::Affine3d& pose) {
  TriMesh result = mesh;
  result.V = (mesh.V * pose.linear().transpose()).rowwise() + pose.translation().transpose();
  return result;
}

// A real scanned shape: the FIND foot template (metres, 1,750 triangles). It is a foot, not a
// last, but it has a sole, a flat ankle cut and a taller heel end: whatever its pose, the same
// canonical mesh must come back.
TEST(OrientFootTemplate, GivesTheSameFrameInAnyPose) {
  const TriMesh foot = test::read_obj_scaled(LASTCUT_SHARED_DATA_DIR "/meshes/find-template-foot.obj", 1000.0);
  ASSERT_EQ(foot.F.rows(), 1750);
  const OrientedLast reference = orient_last(foot);
  for (const std::string& note : reference.notes) std::cout << note << "\n";
  const Eigen::Vector3d size = bounding_box_size(reference.mesh);
  EXPECT_GT(size.x(), 250.0);  // the foot's length lies along X
  EXPECT_LT(size.y(), 120.0);
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const OrientedLast posed = orient_last(transformed(foot, random_rigid(seed)));
    EXPECT_EQ(posed.side, reference.side) << "pose " << seed;
    EXPECT_LT((posed.mesh.V - reference.mesh.V).cwiseAbs().maxCoeff(), 0.5) << "pose " << seed;
  }
}

std::string error_of(const TriMesh& mesh) {
  try {
    orient_last(mesh);
  } catch (const EngineError& error) {
    return error.what();
  }
  return "";
}

TEST(OrientBadInput, ShapesThatAreNotLastsAreRefused) {
  EXPECT_NE(error_of(TriMesh{}), "");
  EXPECT_NE(error_of(test::uv_sphere(50.0, 20, 30)).find("long axis"), std::string::npos);
  // An ellipsoid has a long axis but no sole, no top and no heel.
  TriMesh ellipsoid = test::uv_sphere(50.0, 20, 30);
  ellipsoid.V.col(0) *= 3.0;
  EXPECT_NE(error_of(ellipsoid).find("cannot tell"), std::string::npos) << error_of(ellipsoid);
  // All vertices on one point: no area.
  TriMesh collapsed = test::uv_sphere(50.0, 20, 30);
  collapsed.V.setZero();
  EXPECT_NE(error_of(collapsed), "");
}

}  // namespace
}  // namespace lastcut
