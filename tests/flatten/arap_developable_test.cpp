// ARAP on exactly developable patches of ~50k triangles: the result must be the known development
// (an isometry), up to a rigid motion.
#include <gtest/gtest.h>

#include "engine/flatten/flatten.hpp"
#include "tests/flatten/flatten_fixtures.hpp"

namespace lastcut {
namespace {

void expect_isometric_development(const testing::DevelopablePatch& patch) {
  ASSERT_GE(patch.mesh.triangle_count(), 45000);
  const FlattenResult result = flatten(patch.mesh);
  const DistortionMeasures d = measure_distortion(patch.mesh, result.UV);
  EXPECT_EQ(result.flipped_triangles, 0);
  EXPECT_EQ(d.flipped_triangles, 0);
  EXPECT_LE(d.D_angle, 2.0001);
  EXPECT_LE(d.D_area, 2.0001);
  EXPECT_GE(d.D_angle, 2.0);
  EXPECT_GE(d.D_area, 2.0);
  EXPECT_LE(std::abs(d.boundary_error_pct), 0.05);
  EXPECT_LE(std::abs(d.area_error_pct), 0.05);
  EXPECT_LE(testing::max_distance_after_rigid_alignment(result.UV, patch.development), 0.01);
  EXPECT_EQ(result.factorizations, 1);  // the start map reuses the Laplacian factor
  EXPECT_TRUE(result.converged);
  EXPECT_TRUE(result.notes.empty()) << result.notes.front();
}

TEST(ArapDevelopable, CylinderPatchBecomesItsDevelopment) {
  // 60 mm radius over 150 degrees and 200 mm: like the quarter of a last's leg.
  expect_isometric_development(testing::cylinder_patch(60.0, 150.0, 200.0, 250, 100));
}

TEST(ArapDevelopable, ConePatchBecomesItsDevelopment) {
  expect_isometric_development(testing::cone_patch(30.0, 200.0, 40.0, 180.0, 250, 100));
}

}  // namespace
}  // namespace lastcut
