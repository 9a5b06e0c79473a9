// Stitching seams (`lastcut generate --seams`): where two scan passes were merged the mesh is cut
// along a plane (the crossed triangles split into thin ones) and one pass is misregistered by
// about the asked step. The result must stay one closed, outward, manifold sheet of the same
// solid, so that what the tests meet is a scanner's seam and not a broken mesh.
#include <gtest/gtest.h>

#include <random>

#include "engine/core/engine_error.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/lastgen/stitching_seam.hpp"
#include "mesh_checks.hpp"

namespace lastcut {
namespace {

LastParams seamless_params() {
  LastParams params = LastParams::for_eu_size(41, FootSide::Right);
  params.target_triangles = 20000;
  params.seed = 3;
  return params;
}

TEST(StitchingSeam, CutsTheCrossedTrianglesAndKeepsOneClosedOutwardSheetOfTheSameSolid) {
  const TriMesh seamless = generate_last(seamless_params()).mesh;
  LastParams params = seamless_params();
  params.seams = 2;
  const TriMesh seamed = generate_last(params).mesh;
  // Every crossed edge gains a vertex, every crossed triangle becomes three: a 20k last is crossed
  // by a plane along well over a hundred edges.
  EXPECT_GT(seamed.vertex_count() - seamless.vertex_count(), 200);
  EXPECT_EQ(seamed.triangle_count() - seamless.triangle_count(), 2 * (seamed.vertex_count() - seamless.vertex_count()));
  const test::EdgeCensus census = test::edge_census(seamed);
  EXPECT_EQ(census.boundary_edges, 0);
  EXPECT_EQ(census.non_manifold_edges, 0);
  EXPECT_EQ(census.inconsistent_edges, 0);
  EXPECT_EQ(test::euler_characteristic(seamed), 2);
  EXPECT_NEAR(test::signed_volume_mm3(seamed) / test::signed_volume_mm3(seamless), 1.0, 0.005);
  // Zippering leaves thin triangles where the plane passes near a vertex.
  EXPECT_LT(test::worst_triangle_quality(seamed), 0.5 * test::worst_triangle_quality(seamless));
}

TEST(StitchingSeam, OnePassMovesByAboutTheStepTheOtherStays) {
  const TriMesh seamless = generate_last(seamless_params()).mesh;
  TriMesh seamed = seamless;
  std::mt19937_64 random(11);
  const double step_mm = 0.3;
  add_stitching_seams(seamed, 1, step_mm, random);
  int stayed = 0, moved = 0;
  double largest_mm = 0;
  for (Eigen::Index v = 0; v < seamless.V.rows(); ++v) {  // the original vertices keep their indices
    const double moved_mm = (seamed.V.row(v) - seamless.V.row(v)).norm();
    largest_mm = std::max(largest_mm, moved_mm);
    if (moved_mm == 0.0) ++stayed;
    else if (moved_mm > 0.1 * step_mm) ++moved;
  }
  EXPECT_GT(stayed, 1000) << "the first pass stays where it was";
  EXPECT_GT(moved, 1000) << "the second pass is misregistered";
  EXPECT_LE(largest_mm, 1.3 * step_mm);
  EXPECT_GE(largest_mm, 0.4 * step_mm);
}

TEST(StitchingSeam, TheSameSeedGivesTheSameSeamsAndBadCountsAreRefused) {
  LastParams params = seamless_params();
  params.seams = 3;
  EXPECT_TRUE(generate_last(params).mesh.V == generate_last(params).mesh.V);
  params.seams = 9;
  EXPECT_THROW(generate_last(params), EngineError);
  params.seams = 1;
  params.seam_step_mm = -0.1;
  EXPECT_THROW(generate_last(params), EngineError);
}

}  // namespace
}  // namespace lastcut
