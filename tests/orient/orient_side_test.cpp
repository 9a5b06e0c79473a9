// Naming the foot: a symmetric (straight) last cannot tell left from right by its shape, so the side
// the operator names settles it, and with none it is oriented with neutral halves and a warning. A
// clearly one-footed last keeps its own side when the name disagrees, and says so.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/lastgen/generate_last.hpp"
#include "engine/orient/orient_last.hpp"

namespace lastcut {
namespace {

LastParams symmetric_last(FootSide side, bool random_pose) {
  LastParams params = LastParams::for_eu_size(41, side);
  params.symmetric = true;
  params.target_triangles = 15000;
  params.random_pose = random_pose;
  params.seed = 7;
  return params;
}

// Area-weighted mean Y of the faces within [from, to] of the length (canonical frame).
double mean_y_mm(const TriMesh& mesh, double from, double to) {
  const double length_mm = mesh.V.col(0).maxCoeff();
  const Eigen::VectorXd areas = triangle_areas(mesh);
  double sum = 0.0, weight = 0.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::RowVector3d g = (mesh.V.row(mesh.F(f, 0)) + mesh.V.row(mesh.F(f, 1)) + mesh.V.row(mesh.F(f, 2))) / 3.0;
    if (g.x() < from * length_mm || g.x() > to * length_mm) continue;
    sum += areas(f) * g.y();
    weight += areas(f);
  }
  return sum / weight;
}

TEST(OrientSide, TheSymmetricGeneratorCentresTheToeOnTheHeel) {
  // The generator's own frame: the toe's mean Y as orient_last measures it (heel 0-20 %, toe 85-100 %),
  // against the default last, whose toe leans by several mm.
  const TriMesh symmetric = generate_last(symmetric_last(FootSide::Right, false)).mesh;
  const double offset_mm = mean_y_mm(symmetric, 0.85, 1.0) - mean_y_mm(symmetric, 0.0, 0.2);
  const double length_mm = symmetric.V.col(0).maxCoeff() - symmetric.V.col(0).minCoeff();
  EXPECT_LT(std::abs(offset_mm), 0.25 * kSymmetricToeOffsetShare * length_mm) << offset_mm;
  LastParams ordinary = symmetric_last(FootSide::Right, false);
  ordinary.symmetric = false;
  const TriMesh asymmetric = generate_last(ordinary).mesh;
  EXPECT_GT(mean_y_mm(asymmetric, 0.85, 1.0) - mean_y_mm(asymmetric, 0.0, 0.2), 2.0 * kSymmetricToeOffsetShare * length_mm);
}

TEST(OrientSide, ASymmetricLastWithoutASideIsOrientedWithNeutralHalvesAndAWarning) {
  const OrientedLast last = orient_last(generate_last(symmetric_last(FootSide::Left, true)).mesh);
  EXPECT_TRUE(last.side_unnamed);
  ASSERT_EQ(last.warnings.size(), 1u);
  EXPECT_EQ(last.warnings[0],
            "symmetric last: the side was not named, halves named side_a and side_b; give --side or the sidecar's side "
            "to name them medial/lateral");
}

TEST(OrientSide, TheNamedSideSettlesASymmetricLast) {
  const TriMesh scan = generate_last(symmetric_last(FootSide::Right, true)).mesh;
  for (FootSide side : {FootSide::Left, FootSide::Right}) {
    const OrientedLast last = orient_last(scan, side);
    EXPECT_FALSE(last.side_unnamed);
    EXPECT_EQ(last.side, side);
    EXPECT_TRUE(last.warnings.empty());
  }
}

TEST(OrientSide, AOneFootedLastKeepsItsSideAndWarnsWhenTheNameDisagrees) {
  LastParams params = LastParams::for_eu_size(41, FootSide::Right);
  params.target_triangles = 15000;
  params.random_pose = true;
  const TriMesh scan = generate_last(params).mesh;
  const OrientedLast agreeing = orient_last(scan, FootSide::Right);
  EXPECT_EQ(agreeing.side, FootSide::Right);
  EXPECT_TRUE(agreeing.warnings.empty());
  const OrientedLast disagreeing = orient_last(scan, FootSide::Left);
  EXPECT_EQ(disagreeing.side, FootSide::Right);
  EXPECT_FALSE(disagreeing.side_unnamed);
  ASSERT_EQ(disagreeing.warnings.size(), 1u);
  EXPECT_TRUE(disagreeing.warnings[0].starts_with("the side named is left but the scan is a right last (toe leans "))
      << disagreeing.warnings[0];
  // Same frame either way: the name changes no geometry.
  EXPECT_LT((agreeing.mesh.V - disagreeing.mesh.V).cwiseAbs().maxCoeff(), 1e-12);
}

}  // namespace
}  // namespace lastcut
