// Mold outlines from flat patches: orientation, simplicity, simplification error, allowance,
// notches, refusal of overlapping flattenings, and the outline comparison used for repeatability.
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "engine/core/engine_error.hpp"
#include "engine/mold/boundary_loops.hpp"
#include "engine/mold/mold.hpp"
#include "engine/mold/outline_alignment.hpp"
#include "engine/mold/outline_geometry.hpp"
#include "engine/mold/outline_simplify.hpp"
#include "tests/mold/synthetic_patch.hpp"

namespace lastcut {
namespace {

using test::wavy_disk;

double max_rim_distance(const test::FlatPatch& patch, const Polygon2& outline) {
  double worst = 0.0;
  for (int k = 0; k < patch.rim_count; ++k)
    worst = std::max(worst, closest_outline_point(outline, patch.UV.row(patch.rim_first + k).transpose()).distance_mm);
  return worst;
}

TEST(BoundaryLoops, DiskHasOneLoopInFaceOrder) {
  const auto patch = wavy_disk(64, 3);
  const auto loops = simple_boundary_loops(build_mesh_topology(patch.F, patch.UV.rows()));
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(static_cast<int>(loops[0].size()), patch.rim_count);
  // Faces are CCW, so the loop runs CCW: rim vertex k is followed by k + 1.
  const int at = static_cast<int>(std::find(loops[0].begin(), loops[0].end(), patch.rim_first) - loops[0].begin());
  EXPECT_EQ(loops[0][(at + 1) % loops[0].size()], patch.rim_first + 1);
}

TEST(MakeMold, OutlineIsCounterClockwiseAndSimpleEvenFromClockwiseFaces) {
  auto patch = wavy_disk();
  patch.F.col(1).swap(patch.F.col(2));  // every face clockwise: the boundary loop runs clockwise
  const Mold mold = make_mold("medial", patch.UV, patch.F, {});
  EXPECT_EQ(mold.name, "medial");
  EXPECT_GT(signed_area(mold.outline), 0.0);
  EXPECT_TRUE(is_simple(mold.outline));
}

TEST(MakeMold, SimplificationStaysWithinTolerance) {
  const auto patch = wavy_disk(2000, 6);
  for (double tolerance_mm : {0.02, 0.1, 0.5}) {
    const Mold mold = make_mold("patch", patch.UV, patch.F, {}, {tolerance_mm, 0.0});
    EXPECT_LE(max_rim_distance(patch, mold.outline), tolerance_mm + 1e-9) << tolerance_mm;
    EXPECT_LT(static_cast<int>(mold.outline.points.size()), patch.rim_count) << tolerance_mm;
    EXPECT_TRUE(is_simple(mold.outline));
  }
  // At the default 0.02 mm, most of a smooth curve's 2000 points are redundant.
  const Mold mold = make_mold("patch", patch.UV, patch.F, {});
  EXPECT_LT(mold.outline.points.size(), 1000u);
}

TEST(SimplifyOutline, NeverIntroducesSelfIntersections) {
  // Jagged star polygons: coarse Douglas-Peucker on them would cut across narrow spikes.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> radius_mm(5.0, 50.0);
  for (int trial = 0; trial < 20; ++trial) {
    Polygon2 star;
    const int n = 600;
    for (int k = 0; k < n; ++k) {
      const double theta = 2.0 * std::numbers::pi * k / n;
      const double r = radius_mm(random);
      star.points.emplace_back(r * std::cos(theta), r * std::sin(theta));
    }
    ASSERT_TRUE(is_simple(star));
    for (double tolerance_mm : {2.0, 10.0, 30.0}) {
      const auto kept = simplify_outline(star, tolerance_mm);
      const Polygon2 simplified = select_points(star, kept);
      EXPECT_TRUE(is_simple(simplified)) << "trial " << trial << " tolerance " << tolerance_mm;
      for (const auto& p : star.points)
        ASSERT_LE(closest_outline_point(simplified, p).distance_mm, tolerance_mm + 1e-9);
    }
  }
}

TEST(SimplifyOutline, KeepsRequestedPoints) {
  const auto patch = wavy_disk(400, 2);
  Polygon2 rim;
  for (int k = 0; k < patch.rim_count; ++k) rim.points.push_back(patch.UV.row(patch.rim_first + k).transpose());
  const auto kept = simplify_outline(rim, 1.0, {17, 203});
  EXPECT_NE(std::find(kept.begin(), kept.end(), 17), kept.end());
  EXPECT_NE(std::find(kept.begin(), kept.end(), 203), kept.end());
}

TEST(MakeMold, AllowanceGrowsTheOutlineByTheGivenDistance) {
  const auto patch = wavy_disk(720, 6);
  const Mold net = make_mold("patch", patch.UV, patch.F, {});
  for (double allowance_mm : {1.0, 5.0}) {
    const Mold grown = make_mold("patch", patch.UV, patch.F, {}, {0.02, allowance_mm});
    EXPECT_TRUE(is_simple(grown.outline));
    EXPECT_GT(signed_area(grown.outline), 0.0);
    // Every point of the grown outline is allowance_mm from the net outline (round joins), and
    // every point of the net outline is at least allowance_mm inside (more at concave corners,
    // where the grown outline has a sharp corner).
    for (const auto& p : sample_outline(grown.outline, 0.5)) {
      const double d = closest_outline_point(net.outline, p).distance_mm;
      ASSERT_NEAR(d, allowance_mm, 0.03) << allowance_mm;
      ASSERT_FALSE(test::inside(net.outline, p));
    }
    for (const auto& p : sample_outline(net.outline, 0.5)) {
      ASSERT_GE(closest_outline_point(grown.outline, p).distance_mm, allowance_mm - 0.03);
      ASSERT_TRUE(test::inside(grown.outline, p));
    }
    // Area grows by about perimeter x allowance.
    const double expected_growth = perimeter(net.outline) * allowance_mm;
    EXPECT_NEAR(signed_area(grown.outline) - signed_area(net.outline), expected_growth, 0.1 * expected_growth);
  }
}

TEST(MakeMold, LandmarksBecomeNotchesOnTheOutlinePointingInward) {
  const auto patch = wavy_disk(720, 6);
  const std::map<std::string, int> landmarks{{"toe", patch.rim_first},
                                             {"heel", patch.rim_first + patch.rim_count / 2},
                                             {"top_front", patch.rim_first + 100}};
  for (double allowance_mm : {0.0, 3.0}) {
    const Mold mold = make_mold("lateral", patch.UV, patch.F, landmarks, {0.02, allowance_mm});
    ASSERT_EQ(mold.marks.size(), 3u);
    for (const auto& mark : mold.marks) {
      const Point2 landmark = patch.UV.row(landmarks.at(mark.name)).transpose();
      EXPECT_LT(closest_outline_point(mold.outline, mark.position_mm).distance_mm, 1e-9) << mark.name;
      EXPECT_NEAR((mark.position_mm - landmark).norm(), allowance_mm, 0.05) << mark.name;
      EXPECT_NEAR(mark.inward_direction.norm(), 1.0, 1e-12);
      EXPECT_TRUE(test::inside(mold.outline, mark.position_mm + 0.5 * mark.inward_direction)) << mark.name;
      EXPECT_FALSE(test::inside(mold.outline, mark.position_mm - 0.5 * mark.inward_direction)) << mark.name;
    }
  }
  // Without allowance the notch sits exactly on the landmark vertex (kept by simplification).
  const Mold mold = make_mold("lateral", patch.UV, patch.F, landmarks);
  for (const auto& mark : mold.marks)
    EXPECT_LT((mark.position_mm - Point2(patch.UV.row(landmarks.at(mark.name)))).norm(), 1e-12);
}

TEST(MakeMold, RefusesAnOverlappingFlattening) {
  // A strip wound 1.3 turns around a centre: its flattened outline runs over itself.
  const int along = 200, across = 3;
  Eigen::MatrixXd UV(along * across, 2);
  for (int i = 0; i < along; ++i)
    for (int j = 0; j < across; ++j) {
      const double theta = 1.3 * 2.0 * std::numbers::pi * i / (along - 1);
      const double r = 40.0 + 5.0 * j;
      UV.row(i * across + j) << r * std::cos(theta), r * std::sin(theta);
    }
  Eigen::MatrixXi F(2 * (along - 1) * (across - 1), 3);
  int f = 0;
  for (int i = 0; i + 1 < along; ++i)
    for (int j = 0; j + 1 < across; ++j) {
      const int a = i * across + j, b = a + 1, c = a + across, d = c + 1;
      F.row(f++) << a, b, d;
      F.row(f++) << a, d, c;
    }
  try {
    make_mold("medial", UV, F, {});
    FAIL() << "an overlapping outline was accepted";
  } catch (const EngineError& error) {
    EXPECT_NE(std::string(error.what()).find("overlaps itself"), std::string::npos) << error.what();
  }
}

TEST(MakeMold, RefusesClosedMeshesAndBadInput) {
  Eigen::MatrixXd UV(4, 2);
  UV << 0, 0, 1, 0, 0, 1, 1, 1;
  Eigen::MatrixXi tetrahedron(4, 3);
  tetrahedron << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  EXPECT_THROW(make_mold("x", UV, tetrahedron, {}), EngineError);
  Eigen::MatrixXi one(1, 3);
  one << 0, 1, 2;
  EXPECT_NO_THROW(make_mold("x", UV, one, {}));
  EXPECT_THROW(make_mold("x", UV, one, {{"toe", 9}}), EngineError);
  EXPECT_THROW(make_mold("x", UV, one, {}, {0.02, -1.0}), EngineError);
  Eigen::MatrixXd nan_uv = UV;
  nan_uv(1, 0) = std::nan("");
  EXPECT_THROW(make_mold("x", nan_uv, one, {}), EngineError);
}

// Two triangles touching at one vertex have no single outline: the boundary walk meets a pinch.
TEST(MakeMold, RefusesABowTie) {
  Eigen::MatrixXd UV(5, 2);
  UV << 0, 0, 1, 0, 0, 1, -1, 0, 0, -1;
  Eigen::MatrixXi bow_tie(2, 3);
  bow_tie << 0, 1, 2, 0, 3, 4;
  try {
    make_mold("x", UV, bow_tie, {});
    FAIL() << "a bow tie was accepted";
  } catch (const EngineError& error) {
    EXPECT_NE(std::string(error.what()).find("not a simple loop at vertex 0"), std::string::npos) << error.what();
  }
  // The topology handed in must be the patch's own.
  const MeshTopology other = build_mesh_topology(bow_tie.topRows(1), 5);
  EXPECT_THROW(make_mold("x", UV, bow_tie, {}, {}, other), EngineError);
}

TEST(OutlineAlignment, RecoversARigidMotionAndMeasuresHausdorff) {
  const auto patch = wavy_disk(720, 6);
  const std::map<std::string, int> landmarks{{"toe", patch.rim_first}, {"heel", patch.rim_first + 360}};
  const Mold fixed = make_mold("m", patch.UV, patch.F, landmarks);
  RigidTransform2 motion;
  const double angle = 0.7;
  motion.rotation << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  motion.translation = Point2(120.0, -35.0);
  Mold moving = fixed;
  moving.outline = transformed(fixed.outline, motion);
  for (auto& mark : moving.marks) mark.position_mm = motion.apply(mark.position_mm);
  EXPECT_GT(hausdorff_distance_mm(moving.outline, fixed.outline), 50.0);
  const RigidTransform2 back = align_molds(moving, fixed);
  EXPECT_LT(hausdorff_distance_mm(transformed(moving.outline, back), fixed.outline), 1e-3);
  // Without marks: principal axes and ICP.
  moving.marks.clear();
  const RigidTransform2 back_without_marks = align_molds(moving, fixed);
  EXPECT_LT(hausdorff_distance_mm(transformed(moving.outline, back_without_marks), fixed.outline), 1e-3);

  // Hausdorff of two concentric squares is the gap between them.
  Polygon2 small{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}};
  Polygon2 big{{{-2, -2}, {12, -2}, {12, 12}, {-2, 12}}};
  EXPECT_NEAR(hausdorff_distance_mm(small, big), 2.0 * std::sqrt(2.0), 1e-9);
}

}  // namespace
}  // namespace lastcut
