// ARAP on the shared reference half (a real scanned foot template, 52,800 triangles, FIND, MIT):
// no flipped triangle in the mold, distortion near the ideal, sizes kept, repairs reported.
#include <gtest/gtest.h>

#include <string>

#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/flatten.hpp"
#include "engine/flatten/tutte_embedding.hpp"
#include "tests/flatten/flatten_fixtures.hpp"

namespace lastcut {
namespace {

TEST(ReferenceHalf, FlattensWithoutFlipsAndWithLowDistortion) {
  const TriMesh half =
      testing::read_off(std::string(LASTCUT_SHARED_DATA_DIR) + "/meshes/find-template-half-52k.off", 1000.0);
  ASSERT_EQ(half.triangle_count(), 52800);
  const FlattenResult result = flatten(half);
  const DistortionMeasures d = measure_distortion(half, result.UV);
  EXPECT_EQ(result.flipped_triangles, 0);
  EXPECT_EQ(d.flipped_triangles, 0);
  EXPECT_EQ(result.factorizations, 2);  // a foot half wraps round: the boundary-first start, then ARAP; no Tutte
  // A foot is far from developable (toes, heel cup): ARAP keeps distortion low but not ideal.
  EXPECT_LT(d.D_angle, 2.15);
  EXPECT_LT(d.D_area, 2.15);
  EXPECT_LT(std::abs(d.area_error_pct), 10.0);
  EXPECT_GT(d.max_stretch, 1.0);
  // The fold at the toe is repaired locally, never by falling back to the Tutte map (D ~2.3 there).
  EXPECT_LT(d.D_angle, 2.12);
  EXPECT_LT(d.D_area, 2.14);
  for (const std::string& note : result.notes) {
    EXPECT_EQ(note.find("could not be repaired"), std::string::npos) << note;
    EXPECT_EQ(note.find('\n'), std::string::npos);
    std::printf("note: %s\n", note.c_str());
  }
  std::printf("iterations %d, D_angle %.4f, D_area %.4f, area error %.2f %%, boundary error %.2f %%\n",
              result.iterations, d.D_angle, d.D_area, d.area_error_pct, d.boundary_error_pct);
}

TEST(ReferenceHalf, StartMapIsFlipFreeOnAConvexOutline) {
  const TriMesh half =
      testing::read_off(std::string(LASTCUT_SHARED_DATA_DIR) + "/meshes/find-template-half-52k.off", 1000.0);
  const MeshTopology topology = check_disk(half);
  ASSERT_GT(topology.boundary_loops[0].size(), 100u);
  const TriangleFrames frames = compute_triangle_frames(half);
  ReducedLaplacian laplacian = build_reduced_pattern(frames, topology, topology.boundary_loops[0].front());
  SparseCholesky factor;
  factor.analyze_pattern(laplacian.matrix);
  const Eigen::MatrixXd start = tutte_embedding(half, frames, topology, laplacian, factor);
  EXPECT_EQ(count_flipped_triangles(half.F, start), 0);
  // The outline is strictly convex and counter-clockwise: every turn is to the left.
  const auto& loop = topology.boundary_loops[0];
  for (size_t i = 0; i < loop.size(); ++i) {
    const Eigen::RowVector2d a = start.row(loop[i]), b = start.row(loop[(i + 1) % loop.size()]),
                             c = start.row(loop[(i + 2) % loop.size()]);
    const Eigen::RowVector2d ab = b - a, bc = c - b;
    ASSERT_GT(ab.x() * bc.y() - ab.y() * bc.x(), 0.0) << "at outline vertex " << i;
  }
}

}  // namespace
}  // namespace lastcut
