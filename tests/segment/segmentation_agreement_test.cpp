// The agreement between two splits (engine/segment/segmentation_agreement.hpp): exactly 100 % with
// itself; the closed-form share on a box and a cylinder cut by two planes through the axis; and on
// generated lasts, the medial areas it finds are the areas of the halves segment_last cuts.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/lastgen/generate_last.hpp"
#include "engine/segment/segment_halves.hpp"
#include "engine/segment/segmentation_agreement.hpp"

#include "tests/segment/foot_side_param_name.hpp"

namespace lastcut {
namespace {

using test::side_name;

// A band with no sole and no top: every face between the contours (sole and top fields < 0).
BandCut band_of(TriMesh mesh) {
  BandCut band;
  band.fields = Eigen::MatrixXd::Constant(mesh.V.rows(), 3, -1.0);
  band.fields.col(kPlaneField).setZero();
  band.mesh = std::move(mesh);
  band.snap_fraction = 0.0;
  return band;
}

// Adds the rectangle corner + s u + t v (s, t in [0, 1]) as an n_u x n_v grid of triangle pairs.
void add_grid(TriMesh& mesh, const Eigen::Vector3d& corner, const Eigen::Vector3d& u, const Eigen::Vector3d& v, int n_u, int n_v) {
  const auto first = static_cast<int>(mesh.V.rows());
  mesh.V.conservativeResize(first + (n_u + 1) * (n_v + 1), 3);
  for (int i = 0; i <= n_u; ++i)
    for (int j = 0; j <= n_v; ++j)
      mesh.V.row(first + i * (n_v + 1) + j) = (corner + u * (double(i) / n_u) + v * (double(j) / n_v)).transpose();
  const auto face = static_cast<int>(mesh.F.rows());
  mesh.F.conservativeResize(face + 2 * n_u * n_v, 3);
  int f = face;
  for (int i = 0; i < n_u; ++i)
    for (int j = 0; j < n_v; ++j) {
      const int a = first + i * (n_v + 1) + j, b = a + 1, c = a + n_v + 1, d = c + 1;
      mesh.F.row(f++) << a, c, d;
      mesh.F.row(f++) << a, d, b;
    }
}

// A vertical plane through the z axis at angle_rad from the x axis, medial side to the left of it.
SplitPlane vertical_plane(double angle_rad) {
  SplitPlane plane;
  plane.normal = Eigen::Vector3d(-std::sin(angle_rad), std::cos(angle_rad), 0.0);
  plane.offset = 0.0;
  return plane;
}

TEST(SplitAgreement, BoxWallsCutByTwoPlanesThroughTheAxis) {
  // Walls of the box |x| <= a, |y| <= b, 0 <= z <= h. Planes y = 0 and the same turned by theta
  // about z disagree on the wedges 0 < angle < theta and pi < angle < pi + theta, which meet the
  // walls x = +-a over a strip a tan(theta) wide: agreement = 1 - 2 a tan(theta) h / (4 (a + b) h).
  const double a = 40.0, b = 30.0, h = 25.0;
  TriMesh walls;
  walls.V.resize(0, 3);
  walls.F.resize(0, 3);
  add_grid(walls, {a, -b, 0}, {0, 2 * b, 0}, {0, 0, h}, 37, 5);
  add_grid(walls, {-a, -b, 0}, {0, 2 * b, 0}, {0, 0, h}, 41, 7);
  add_grid(walls, {-a, b, 0}, {2 * a, 0, 0}, {0, 0, h}, 29, 3);
  add_grid(walls, {-a, -b, 0}, {2 * a, 0, 0}, {0, 0, h}, 33, 4);
  const BandCut band = band_of(walls);
  for (double theta_deg : {3.0, 10.0, 25.0}) {
    const double theta = theta_deg * std::numbers::pi / 180.0;
    const SplitAgreement agreement = split_agreement(band, vertical_plane(0.0), vertical_plane(theta));
    const double expected = 100.0 * (1.0 - a * std::tan(theta) / (2.0 * (a + b)));
    EXPECT_NEAR(agreement.band_area_mm2, 4.0 * (a + b) * h, 1e-9);
    EXPECT_NEAR(agreement.percent(), expected, 1e-9) << theta_deg;
    EXPECT_NEAR(agreement.medial_a_mm2, 2.0 * (a + b) * h, 1e-9);
    // The same with the roles swapped.
    EXPECT_NEAR(split_agreement(band, vertical_plane(theta), vertical_plane(0.0)).percent(), expected, 1e-9);
  }
}

TEST(SplitAgreement, CylinderCutByTwoPlanesThroughTheAxis) {
  // Two planes through a cylinder's axis at theta apart disagree on 2 theta of its 2 pi: agreement
  // = 100 (1 - theta / pi). The mesh is a 720-sided prism, wedges not aligned with its vertices.
  const int sides = 720, rings = 6;
  const double radius = 50.0, height = 80.0;
  TriMesh tube;
  tube.V.resize(sides * (rings + 1), 3);
  for (int s = 0; s < sides; ++s)
    for (int r = 0; r <= rings; ++r) {
      const double angle = 2.0 * std::numbers::pi * (s + 0.37) / sides;
      tube.V.row(s * (rings + 1) + r) << radius * std::cos(angle), radius * std::sin(angle), height * r / rings;
    }
  tube.F.resize(2 * sides * rings, 3);
  int f = 0;
  for (int s = 0; s < sides; ++s)
    for (int r = 0; r < rings; ++r) {
      const int a = s * (rings + 1) + r, b = a + 1, c = ((s + 1) % sides) * (rings + 1) + r, d = c + 1;
      tube.F.row(f++) << a, c, d;
      tube.F.row(f++) << a, d, b;
    }
  const BandCut band = band_of(tube);
  for (double theta_deg : {1.3, 7.7, 31.0}) {
    const double theta = theta_deg * std::numbers::pi / 180.0;
    const double got = split_agreement(band, vertical_plane(0.2), vertical_plane(0.2 + theta)).percent();
    const double expected = 100.0 * (1.0 - theta / std::numbers::pi);
    EXPECT_NEAR(got, expected, 0.01 * expected / 100.0) << theta_deg;  // within 0.01 % of the value
  }
}

TEST(SplitAgreement, ASplitAgreesWithItselfExactly) {
  TriMesh walls;
  walls.V.resize(0, 3);
  walls.F.resize(0, 3);
  add_grid(walls, {0, 0, 0}, {100, 0, 0}, {0, 30, 40}, 23, 11);
  BandCut band = band_of(walls);
  band.snap_fraction = 0.1;
  const SplitPlane tilted = [] {
    SplitPlane p;
    p.normal = Eigen::Vector3d(0.3, 0.8, -0.2).normalized();
    p.offset = -7.0;
    return p;
  }();
  const SplitAgreement self = split_agreement(band, tilted, tilted);
  EXPECT_EQ(self.percent(), 100.0);
  EXPECT_EQ(self.disagreement_mm2, 0.0);
  EXPECT_GT(self.medial_a_mm2, 0.0);
  EXPECT_LT(self.medial_a_mm2, self.band_area_mm2);
}

class SplitAgreementOnLasts : public testing::TestWithParam<FootSide> {};

TEST_P(SplitAgreementOnLasts, MedialAreasAreTheCutHalvesAreas) {
  const FootSide side = GetParam();
  LastParams params = LastParams::for_eu_size(side == FootSide::Left ? 41 : 36, side);
  params.target_triangles = 30000;
  params.noise_mm = 0.2;
  const OrientedLast last{generate_last(params).mesh, Eigen::Affine3d::Identity(), side, {}};
  SegmentOptions expert;
  expert.split_rule = SplitRule::Expert;
  const BandCut band = cut_band(last, expert);
  const SplitPlane automatic_plane = place_split_plane(band, SegmentOptions{}), expert_plane = place_split_plane(band, expert);
  const Segmentation automatic = split_band(band, automatic_plane), by_expert = split_band(band, expert_plane);
  const SplitAgreement agreement = split_agreement(band, automatic_plane, expert_plane);
  const double medial_a = surface_area(automatic.medial.mesh), lateral_a = surface_area(automatic.lateral.mesh);
  const double medial_b = surface_area(by_expert.medial.mesh), lateral_b = surface_area(by_expert.lateral.mesh);
  EXPECT_NEAR(agreement.medial_a_mm2, medial_a, 1e-9 * medial_a);
  EXPECT_NEAR(agreement.medial_b_mm2, medial_b, 1e-9 * medial_b);
  EXPECT_NEAR(agreement.band_area_mm2, medial_a + lateral_a, 1e-9 * agreement.band_area_mm2);
  EXPECT_NEAR(agreement.band_area_mm2, medial_b + lateral_b, 1e-9 * agreement.band_area_mm2);
  // Disagreement is at least the difference of the medial areas (one half grows by what the other loses).
  EXPECT_GE(agreement.disagreement_mm2, std::abs(medial_a - medial_b) - 1e-6);
  EXPECT_GT(agreement.percent(), 80.0);
  EXPECT_LT(agreement.percent(), 100.0);
  EXPECT_NEAR(split_agreement(band, expert_plane, automatic_plane).percent(), agreement.percent(), 1e-9);
  EXPECT_EQ(split_agreement(band, expert_plane, expert_plane).percent(), 100.0);
}

INSTANTIATE_TEST_SUITE_P(Sides, SplitAgreementOnLasts, testing::Values(FootSide::Left, FootSide::Right),
                         side_name);

}  // namespace
}  // namespace lastcut
