// Flattening on small meshes: bad input refused with one readable line, rigid-motion invariance, LSCM,
// flip detection, distortion measures on known maps, and ARAP vs LSCM on a doubly curved cap.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>

#include "engine/core/engine_error.hpp"
#include "engine/flatten/flatten.hpp"
#include "tests/flatten/flatten_fixtures.hpp"

namespace lastcut {
namespace {

std::string error_of(const TriMesh& mesh) {
  try {
    flatten(mesh);
  } catch (const EngineError& e) {
    return e.what();
  }
  return "";
}

TEST(FlattenInput, RefusesWhatIsNotADiskWithOneLine) {
  const TriMesh patch = testing::cylinder_patch(30.0, 90.0, 40.0, 6, 4).mesh;

  TriMesh tetrahedron;
  tetrahedron.V.resize(4, 3);
  tetrahedron.V << 0, 0, 0, 10, 0, 0, 0, 10, 0, 0, 0, 10;
  tetrahedron.F.resize(4, 3);
  tetrahedron.F << 0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2;
  EXPECT_NE(error_of(tetrahedron).find("closed surface"), std::string::npos) << error_of(tetrahedron);

  TriMesh two_pieces = patch;
  two_pieces.V.conservativeResize(2 * patch.V.rows(), 3);
  two_pieces.V.bottomRows(patch.V.rows()) = patch.V.rowwise() + Eigen::RowVector3d(100, 0, 0);
  two_pieces.F.conservativeResize(2 * patch.F.rows(), 3);
  two_pieces.F.bottomRows(patch.F.rows()) = patch.F.array() + static_cast<int>(patch.V.rows());
  EXPECT_NE(error_of(two_pieces).find("2 separate pieces"), std::string::npos) << error_of(two_pieces);

  const TriMesh ring = testing::cylinder_patch(30.0, 360.0, 40.0, 12, 3).mesh;  // seam not welded: still a disk
  EXPECT_EQ(error_of(ring), "");
  TriMesh tube;  // weld the seam (column 12 onto column 0): a tube has two boundary loops
  tube.V.resize(12 * 4, 3);
  for (int v = 0; v < 13 * 4; ++v) {
    if (v % 13 != 12) tube.V.row(v / 13 * 12 + v % 13) = ring.V.row(v);
  }
  tube.F = ring.F.unaryExpr([](int v) { return v / 13 * 12 + v % 13 % 12; });
  EXPECT_NE(error_of(tube).find("more than one boundary loop"), std::string::npos) << error_of(tube);

  TriMesh unused = patch;
  unused.V.conservativeResize(patch.V.rows() + 1, 3);
  unused.V.bottomRows(1).setZero();
  EXPECT_NE(error_of(unused).find("not used by any triangle"), std::string::npos);

  TriMesh out_of_range = patch;
  out_of_range.F(3, 1) = 999;
  EXPECT_NE(error_of(out_of_range).find("does not exist"), std::string::npos);

  TriMesh flipped_face = patch;
  std::swap(flipped_face.F(5, 1), flipped_face.F(5, 2));
  EXPECT_NE(error_of(flipped_face).find("same orientation"), std::string::npos) << error_of(flipped_face);

  TriMesh sliver = patch;
  sliver.V.row(sliver.F(7, 2)) = 0.5 * (sliver.V.row(sliver.F(7, 0)) + sliver.V.row(sliver.F(7, 1)));
  EXPECT_NE(error_of(sliver).find("zero area"), std::string::npos) << error_of(sliver);

  TriMesh not_finite = patch;
  not_finite.V(2, 1) = std::nan("");
  EXPECT_NE(error_of(not_finite).find("non-finite"), std::string::npos);

  EXPECT_NE(error_of(TriMesh{}).find("empty"), std::string::npos);
  for (const TriMesh* bad : {&tetrahedron, &two_pieces, &tube, &unused, &sliver}) {
    EXPECT_EQ(error_of(*bad).find('\n'), std::string::npos);
  }
}

TEST(FlattenInput, SmallPatchFlattensCleanly) {
  const testing::DevelopablePatch patch = testing::cylinder_patch(25.0, 120.0, 30.0, 12, 8);
  const FlattenResult result = flatten(patch.mesh);
  EXPECT_EQ(result.UV.rows(), patch.mesh.V.rows());
  EXPECT_EQ(result.flipped_triangles, 0);
  EXPECT_LE(testing::max_distance_after_rigid_alignment(result.UV, patch.development), 1e-3);
  EXPECT_NEAR(result.UV.colwise().mean().norm(), 0.0, 1e-9);
}

TEST(FlattenInvariance, RigidMotionOfTheMeshDoesNotChangeTheMold) {
  const TriMesh cap = testing::spherical_cap(80.0, 50.0, 12, 40);
  const Eigen::Affine3d motion = Eigen::Translation3d(250.0, -40.0, 1000.0) *
                                 Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, -0.8, 0.5).normalized());
  TriMesh moved = cap;
  moved.V = ((motion.linear() * cap.V.transpose()).colwise() + motion.translation()).transpose();
  for (FlattenMethod method : {FlattenMethod::Arap, FlattenMethod::Lscm}) {
    FlattenOptions options;
    options.method = method;
    const FlattenResult a = flatten(cap, options);
    const FlattenResult b = flatten(moved, options);
    EXPECT_EQ(a.iterations, b.iterations);
    EXPECT_LT((a.UV - b.UV).cwiseAbs().maxCoeff(), 1e-6);
  }
}

TEST(Lscm, DevelopsACylinderPatchAndIsConformalOnACap) {
  const testing::DevelopablePatch patch = testing::cylinder_patch(40.0, 100.0, 60.0, 30, 20);
  FlattenOptions options;
  options.method = FlattenMethod::Lscm;
  const FlattenResult developed = flatten(patch.mesh, options);
  EXPECT_EQ(developed.factorizations, 1);
  EXPECT_EQ(developed.iterations, 0);
  EXPECT_LE(testing::max_distance_after_rigid_alignment(developed.UV, patch.development), 1e-6);

  const TriMesh cap = testing::spherical_cap(60.0, 60.0, 20, 60);
  const FlattenResult conformal = flatten(cap, options);
  const DistortionMeasures lscm = measure_distortion(cap, conformal.UV);
  EXPECT_EQ(lscm.flipped_triangles, 0);
  EXPECT_NEAR(lscm.area_error_pct, 0.0, 1e-9);  // scaled to the 3D area
  EXPECT_LT(lscm.D_angle, 2.01);

  const DistortionMeasures arap = measure_distortion(cap, flatten(cap).UV);
  // The thesis' finding: ARAP trades a little angle distortion for much less area distortion.
  EXPECT_LT(arap.D_area, lscm.D_area);
  EXPECT_GT(arap.D_angle, lscm.D_angle);
  EXPECT_LT(std::abs(arap.boundary_error_pct), std::abs(lscm.boundary_error_pct));
}

TEST(Distortion, MeasuresKnownMapsAndCountsFlips) {
  // Unit right triangle pair in the plane, mapped by known linear maps.
  const TriMesh square = testing::square_10mm();
  const Eigen::MatrixXd identity = square.V.leftCols(2);
  DistortionMeasures d = measure_distortion(square, identity);
  EXPECT_DOUBLE_EQ(d.D_angle, 2.0);
  EXPECT_DOUBLE_EQ(d.D_area, 2.0);
  EXPECT_EQ(d.flipped_triangles, 0);
  EXPECT_NEAR(d.boundary_error_pct, 0.0, 1e-12);

  Eigen::MatrixXd stretched = identity;
  stretched.col(0) *= 2.0;  // sigma = (2, 1): D_angle = 2.5, D_area = 2 + 1/2
  d = measure_distortion(square, stretched);
  EXPECT_NEAR(d.D_angle, 2.5, 1e-12);
  EXPECT_NEAR(d.D_area, 2.5, 1e-12);
  EXPECT_NEAR(d.area_error_pct, 100.0, 1e-9);
  EXPECT_NEAR(d.max_stretch, 2.0, 1e-12);
  EXPECT_NEAR(d.p95_stretch, 2.0, 1e-12);
  EXPECT_NEAR(d.boundary_error_pct, 50.0, 1e-9);

  Eigen::MatrixXd folded = identity;
  folded.row(3) << 15.0, 5.0;  // vertex 3 pulled across the diagonal: triangle 1 flips
  d = measure_distortion(square, folded);
  EXPECT_EQ(d.flipped_triangles, 1);
  EXPECT_EQ(count_flipped_triangles(square.F, folded), 1);
  EXPECT_LT(d.area_2d_mm2, d.area_3d_mm2);

  Eigen::MatrixXd mirrored = identity;
  mirrored.col(0) *= -1.0;
  EXPECT_EQ(count_flipped_triangles(square.F, mirrored), 2);

  EXPECT_THROW(measure_distortion(square, Eigen::MatrixXd::Zero(3, 2)), EngineError);
}

}  // namespace
}  // namespace lastcut
