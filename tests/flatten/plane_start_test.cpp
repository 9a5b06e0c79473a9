// The ARAP start map from rotations onto the mean plane: exact on a developable patch, pose-independent,
// one factorization in total (options.start = ArapStart::PlaneRotation; the default start is
// boundary_first_start.hpp); the Tutte map is still used where the half faces no one way or when a
// flip-guarded run is asked for.
#include <gtest/gtest.h>

#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/flatten.hpp"
#include "engine/flatten/plane_rotation_start.hpp"
#include "tests/flatten/flatten_fixtures.hpp"

namespace lastcut {
namespace {

FlattenOptions plane_start_options() {
  FlattenOptions options;
  options.start = ArapStart::PlaneRotation;
  return options;
}

std::optional<Eigen::MatrixXd> start_of(const TriMesh& mesh) {
  const MeshTopology topology = check_disk(mesh);
  const TriangleFrames frames = compute_triangle_frames(mesh);
  ReducedLaplacian laplacian = pinned_cotangent_laplacian(frames, topology);
  SparseCholesky factor;
  factor.analyze_pattern(laplacian.matrix);
  factor.factorize(laplacian.matrix);
  return plane_rotation_start(mesh, frames, topology, laplacian, factor);
}

TEST(PlaneRotationStart, IsTheDevelopmentOfACylinderPatch) {
  // Cylinder over 150 degrees: every triangle turned onto the mean plane by its smallest rotation (about
  // the cylinder's axis) lands exactly where the development puts it.
  const testing::DevelopablePatch patch = testing::cylinder_patch(50.0, 150.0, 80.0, 40, 20);
  const std::optional<Eigen::MatrixXd> start = start_of(patch.mesh);
  ASSERT_TRUE(start.has_value());
  EXPECT_EQ(count_flipped_triangles(patch.mesh.F, *start), 0);
  EXPECT_LE(testing::max_distance_after_rigid_alignment(*start, patch.development), 1e-6);
}

TEST(PlaneRotationStart, IsCloseToTheDevelopmentOfAConePatch) {
  // On a cone the smallest rotations do not all turn about one axis: the stitched map is near, not at,
  // the development, and far nearer than the Tutte map.
  const testing::DevelopablePatch patch = testing::cone_patch(30.0, 100.0, 40.0, 120.0, 40, 20);
  const std::optional<Eigen::MatrixXd> start = start_of(patch.mesh);
  ASSERT_TRUE(start.has_value());
  EXPECT_EQ(count_flipped_triangles(patch.mesh.F, *start), 0);
  EXPECT_LE(testing::max_distance_after_rigid_alignment(*start, patch.development), 0.02 * 120.0);
  FlattenOptions tutte_start;
  tutte_start.flip_guard = true;
  const FlattenResult from_tutte = flatten(patch.mesh, tutte_start);
  const FlattenResult from_plane = flatten(patch.mesh, plane_start_options());
  EXPECT_LT(from_plane.energy_start, 0.05 * from_tutte.energy_start);
  EXPECT_LE(from_plane.iterations, from_tutte.iterations);
  std::printf("start energy %.4g (Tutte %.4g), iterations %d (Tutte, flip-guarded %d)\n", from_plane.energy_start,
              from_tutte.energy_start, from_plane.iterations, from_tutte.iterations);
}

TEST(PlaneRotationStart, RefusedWhenTheHalfFacesNoOneWayAndTutteIsUsed) {
  // A 350-degree sleeve: its normals nearly cancel out.
  const TriMesh sleeve = testing::cylinder_patch(30.0, 350.0, 40.0, 60, 10).mesh;
  EXPECT_FALSE(start_of(sleeve).has_value());
  const FlattenResult result = flatten(sleeve, plane_start_options());
  EXPECT_EQ(result.factorizations, 2);
  ASSERT_FALSE(result.notes.empty());
  EXPECT_NE(result.notes.front().find("Tutte"), std::string::npos) << result.notes.front();
}

TEST(PlaneRotationStart, FlipGuardedRunStartsFromTheFlipFreeTutteMap) {
  const testing::DevelopablePatch patch = testing::cylinder_patch(50.0, 120.0, 80.0, 30, 15);
  FlattenOptions options;
  options.flip_guard = true;
  const FlattenResult guarded = flatten(patch.mesh, options);
  EXPECT_EQ(guarded.factorizations, 2);
  EXPECT_EQ(guarded.flipped_triangles, 0);
  const FlattenResult free_run = flatten(patch.mesh, plane_start_options());
  EXPECT_EQ(free_run.factorizations, 1);
  // The developed start is already at the minimum; from the Tutte map ARAP has to iterate there.
  EXPECT_LT(free_run.energy_start, 1e-6 * guarded.energy_start);
}

}  // namespace
}  // namespace lastcut

namespace lastcut {
namespace {

TEST(PlaneRotationStart, AreaFacingAwayIsTheSweepBeyondHalfATurn) {
  // A cylinder patch over sweep s (centred on the mean normal) faces away from it beyond +-90 degrees:
  // the share is (s - 180) / s for s > 180, else 0. The fine grid keeps the facet error small.
  EXPECT_NEAR(area_facing_away_share(testing::cylinder_patch(40.0, 150.0, 60.0, 300, 4).mesh), 0.0, 1e-12);
  EXPECT_NEAR(area_facing_away_share(testing::cylinder_patch(40.0, 270.0, 60.0, 540, 4).mesh), 1.0 / 3.0, 0.005);
  // The default start follows it: one factorization for the patch that faces one way (plane start),
  // two (boundary-first start, then ARAP) for the one that wraps round.
  EXPECT_EQ(flatten(testing::cylinder_patch(40.0, 150.0, 60.0, 60, 8).mesh).factorizations, 1);
  EXPECT_EQ(flatten(testing::cylinder_patch(40.0, 270.0, 60.0, 108, 8).mesh).factorizations, 2);
}

}  // namespace
}  // namespace lastcut
