// The FIND foot template (a real scanned shape, 1,750 triangles, metres; see
// ../shared/data/README.md): a foot is not a last, but with its flat ankle cut and its sole it
// must still come apart into two disk halves of similar area, with (almost) nothing of the sole
// or the ankle cut left in them. It is checked as it is (edges ~10 mm, far coarser than a scan,
// so a smooth cut runs through whole flat facets) and subdivided 1:16 to scan density.
#include <gtest/gtest.h>

#include <iostream>
#include <numbers>

#include "engine/orient/orient_last.hpp"
#include "engine/segment/segment_last.hpp"
#include "segment_test_support.hpp"

namespace lastcut {
namespace {

struct LeftOvers {
  double steep_down_share;  // of the half's area, facing down more steeply than 70 degrees
  double top_cut_share;     // of the half's area, facing up within 20 degrees near the top
};

LeftOvers left_overs(const TriMesh& half, double top_z_mm) {
  const Eigen::VectorXd elevation = test::face_elevation_rad(half), areas = triangle_areas(half);
  double steep = 0.0, top = 0.0;
  for (Eigen::Index f = 0; f < elevation.size(); ++f) {
    const double z = (half.V(half.F(f, 0), 2) + half.V(half.F(f, 1), 2) + half.V(half.F(f, 2), 2)) / 3.0;
    if (elevation(f) < -70.0 * std::numbers::pi / 180.0) steep += areas(f);
    if (elevation(f) > 70.0 * std::numbers::pi / 180.0 && z > top_z_mm - 3.0) top += areas(f);
  }
  return {steep / areas.sum(), top / areas.sum()};
}

void expect_two_clean_halves(const TriMesh& foot, double max_top_share) {
  const OrientedLast last = orient_last(foot);
  const Segmentation result = segment_last(last);
  for (const std::string& note : result.notes) std::cout << note << "\n";
  const double top_z = last.mesh.V.col(2).maxCoeff();
  for (const Segment* half : {&result.medial, &result.lateral}) {
    SCOPED_TRACE(half->name);
    EXPECT_EQ(test::boundary_loops_of(half->mesh).size(), 1u);
    EXPECT_EQ(test::euler_characteristic_of(half->mesh), 1);
    EXPECT_EQ(half->landmarks.size(), 4u);
    const LeftOvers left = left_overs(half->mesh, top_z);
    std::cout << half->name << ": steep-down share " << left.steep_down_share << ", top-cut share " << left.top_cut_share << "\n";
    EXPECT_LT(left.steep_down_share, 0.002);
    EXPECT_LT(left.top_cut_share, max_top_share);
  }
  const double ratio = surface_area(result.medial.mesh) / surface_area(result.lateral.mesh);
  EXPECT_GT(ratio, 1.0 / 1.2);
  EXPECT_LT(ratio, 1.2);
}

TEST(SegmentFootTemplate, AsScannedGivesTwoDiskHalvesOfSimilarArea) {
  const TriMesh foot = test::read_obj_scaled(LASTCUT_SHARED_DATA_DIR "/meshes/find-template-foot.obj", 1000.0);
  ASSERT_EQ(foot.F.rows(), 1750);
  expect_two_clean_halves(foot, 0.01);
}

TEST(SegmentFootTemplate, AtScanDensityLeavesTheAnkleCutOut) {
  const TriMesh foot = test::read_obj_scaled(LASTCUT_SHARED_DATA_DIR "/meshes/find-template-foot.obj", 1000.0);
  expect_two_clean_halves(test::midpoint_subdivided(foot, 2), 0.002);
}

}  // namespace
}  // namespace lastcut
