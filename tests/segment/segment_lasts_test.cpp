// Segmentation of generated lasts (sizes, both sides, random pose, 0.2 mm noise, scan holes):
// two disk halves of similar area, sole and top cut removed, smooth boundaries, the medial half on
// the medial side, landmarks at the four corners; and the same result every run.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "engine/lastgen/generate_last.hpp"
#include "engine/orient/orient_last.hpp"
#include "engine/segment/region_contour.hpp"
#include "engine/segment/segment_last.hpp"
#include "engine/segment/surface_regions.hpp"
#include "segment_test_support.hpp"
#include "tests/support/last_cases.hpp"

namespace lastcut {
namespace {

using test::LastCase;

OrientedLast scanned_last(const LastCase& c, int triangles) {
  LastParams params = LastParams::for_eu_size(c.eu_size, c.side);
  params.target_triangles = triangles;
  params.noise_mm = 0.2;
  params.holes = 3;
  params.random_pose = true;
  params.seed = c.seed;
  return orient_last(generate_last(params).mesh);
}

double mean_y(const TriMesh& mesh) {
  const Eigen::VectorXd areas = triangle_areas(mesh);
  double sum = 0.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    sum += areas(f) * (mesh.V(mesh.F(f, 0), 1) + mesh.V(mesh.F(f, 1), 1) + mesh.V(mesh.F(f, 2), 1)) / 3.0;
  return sum / areas.sum();
}

// Share of the half's area (0..1) in faces whose normal points down more steeply than limit_deg.
double steep_down_share(const TriMesh& half, double limit_deg) {
  const Eigen::VectorXd elevation = test::face_elevation_rad(half), areas = triangle_areas(half);
  double steep = 0.0;
  for (Eigen::Index f = 0; f < areas.size(); ++f)
    if (elevation(f) < -limit_deg * std::numbers::pi / 180.0) steep += areas(f);
  return steep / areas.sum();
}

// Area (mm^2) of the half's faces that lie on the flat top cut: facing up within 20 degrees and
// within 3 mm below the last's highest point.
double area_on_top_cut(const TriMesh& half, double top_z_mm) {
  const Eigen::VectorXd elevation = test::face_elevation_rad(half), areas = triangle_areas(half);
  double area = 0.0;
  for (Eigen::Index f = 0; f < areas.size(); ++f) {
    const double z = (half.V(half.F(f, 0), 2) + half.V(half.F(f, 1), 2) + half.V(half.F(f, 2), 2)) / 3.0;
    if (elevation(f) > 70.0 * std::numbers::pi / 180.0 && z > top_z_mm - 3.0) area += areas(f);
  }
  return area;
}

class SegmentGeneratedLast : public testing::TestWithParam<LastCase> {};

TEST_P(SegmentGeneratedLast, GivesTwoSmoothDiskHalvesOnTheRightSides) {
  const LastCase c = GetParam();
  const OrientedLast last = scanned_last(c, 24000);
  ASSERT_EQ(last.side, c.side);
  const Segmentation result = segment_last(last);
  const double last_area = surface_area(last.mesh), top_z = last.mesh.V.col(2).maxCoeff();
  const double length = last.mesh.V.col(0).maxCoeff();

  for (const Segment* half : {&result.medial, &result.lateral}) {
    SCOPED_TRACE(half->name);
    const auto loops = test::boundary_loops_of(half->mesh);
    ASSERT_EQ(loops.size(), 1u);
    EXPECT_EQ(test::euler_characteristic_of(half->mesh), 1);
    EXPECT_GT(surface_area(half->mesh), 0.25 * last_area);

    const double steep = steep_down_share(half->mesh, 70.0), on_top = area_on_top_cut(half->mesh, top_z);
    EXPECT_LT(steep, 0.002) << "share of the half facing steeply down (sole left in)";
    EXPECT_LT(on_top, 20.0) << "mm^2 of the flat top cut left in the half";

    std::vector<int> corners;
    for (const char* name : {"toe", "heel", "top_front", "top_back"}) {
      ASSERT_TRUE(half->landmarks.contains(name)) << name;
      const int v = half->landmarks.at(name);
      EXPECT_NE(std::find(loops[0].begin(), loops[0].end(), v), loops[0].end()) << name << " is not on the boundary";
      corners.push_back(v);
    }
    const auto point = [&](const char* name) { return Eigen::Vector3d(half->mesh.V.row(half->landmarks.at(name))); };
    EXPECT_GT(point("toe").x(), 0.9 * length);
    EXPECT_LT(point("heel").x(), 0.1 * length);
    EXPECT_LT(point("toe").z(), 0.3 * top_z);
    EXPECT_GT(point("top_front").z(), 0.6 * top_z);
    EXPECT_GT(point("top_back").z(), 0.6 * top_z);
    EXPECT_GT(point("top_front").x(), point("top_back").x());

    const test::BoundarySmoothness smooth = test::boundary_smoothness(half->mesh, loops[0], corners, 6.0);
    std::cout << half->name << ": area " << surface_area(half->mesh) << " mm^2, steep share " << steep << ", on top "
              << on_top << " mm^2, max turn " << smooth.max_turning_deg << " deg, staircase " << smooth.staircase_ratio << "\n";
    // A staircase of whole triangles scores > 80 deg and > 1.1 (see the test below).
    EXPECT_LT(smooth.max_turning_deg, 45.0);
    EXPECT_LT(smooth.staircase_ratio, 1.03);
  }
  const double ratio = surface_area(result.medial.mesh) / surface_area(result.lateral.mesh);
  EXPECT_GT(ratio, 1.0 / 1.2);
  EXPECT_LT(ratio, 1.2);
  EXPECT_GT(mean_y(result.medial.mesh) * medial_y_sign(c.side), 0.0) << "the medial half is not on the medial side";
  EXPECT_LT(mean_y(result.lateral.mesh) * medial_y_sign(c.side), 0.0);
  EXPECT_GT(result.lower_contour.size(), 50u);
  EXPECT_GT(result.upper_contour.size(), 20u);
}

INSTANTIATE_TEST_SUITE_P(Sizes, SegmentGeneratedLast,
                         testing::Values(LastCase{35, FootSide::Right, 11}, LastCase{39, FootSide::Left, 12},
                                         LastCase{43, FootSide::Right, 13}, LastCase{47, FootSide::Left, 14}),
                         test::last_case_name);

TEST(SegmentGeneratedLast, IsDeterministic) {
  const OrientedLast last = scanned_last({41, FootSide::Left, 21}, 12000);
  const Segmentation first = segment_last(last), second = segment_last(last);
  EXPECT_EQ(first.medial.mesh.V, second.medial.mesh.V);
  EXPECT_EQ(first.medial.mesh.F, second.medial.mesh.F);
  EXPECT_EQ(first.lateral.mesh.V, second.lateral.mesh.V);
  EXPECT_EQ(first.lateral.mesh.F, second.lateral.mesh.F);
  EXPECT_EQ(first.medial.landmarks, second.medial.landmarks);
}

// The smoothness metric must be able to fail: on the staircase of whole triangles that a
// face-region boundary gives, it sees the steps; on the curve the halves were cut along, it does not.
TEST(SegmentGeneratedLast, CutCurvesAreSmoothWhereTriangleBoundariesAreStairs) {
  const OrientedLast last = scanned_last({42, FootSide::Right, 22}, 12000);
  const MeshTopology topology = build_mesh_topology(last.mesh.F, last.mesh.V.rows());
  const std::vector<char> sole =
      sole_region(last.mesh, topology, smoothed_elevation_rad(last.mesh, topology, 3.0), triangle_areas(last.mesh), -std::numbers::pi / 4);
  const test::BoundarySmoothness stairs =
      test::boundary_smoothness(last.mesh, region_boundary_loop(last.mesh, topology, sole), {}, 0.0);

  const Segmentation result = segment_last(last);
  TriMesh contour;
  contour.V.resize(static_cast<Eigen::Index>(result.lower_contour.size()), 3);
  std::vector<int> order;
  for (std::size_t i = 0; i < result.lower_contour.size(); ++i) {
    contour.V.row(static_cast<Eigen::Index>(i)) = result.lower_contour[i].transpose();
    order.push_back(static_cast<int>(i));
  }
  const test::BoundarySmoothness cut = test::boundary_smoothness(contour, order, {}, 0.0);
  std::cout << "feather line: triangle boundary turns up to " << stairs.max_turning_deg << " deg, staircase "
            << stairs.staircase_ratio << "; cut curve " << cut.max_turning_deg << " deg, " << cut.staircase_ratio << "\n";
  EXPECT_GT(stairs.staircase_ratio, 1.1);
  EXPECT_GT(stairs.max_turning_deg, 80.0);
  EXPECT_LT(cut.staircase_ratio, 1.02);
  EXPECT_LT(cut.max_turning_deg, 40.0);
}

}  // namespace
}  // namespace lastcut
