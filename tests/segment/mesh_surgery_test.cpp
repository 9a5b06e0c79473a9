// fill_holes and cut_along_zero_level on meshes whose answer is known: a closed UV sphere with
// holes punched in it, and a plane level set through it.
#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>

#include <Eigen/Geometry>
#include <map>

#include "engine/mesh/fill_holes.hpp"
#include "engine/segment/level_set_cut.hpp"
#include "segment_test_support.hpp"

namespace lastcut {
namespace {

// Every edge is used once in each direction: closed and consistently oriented.
bool closed_and_oriented(const TriMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) ++uses[{mesh.F(f, k), mesh.F(f, (k + 1) % 3)}];
  for (const auto& [edge, count] : uses)
    if (count != 1 || !uses.contains({edge.second, edge.first})) return false;
  return true;
}

double enclosed_volume_mm3(const TriMesh& mesh) {
  double six_volume = 0.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    six_volume += Eigen::Vector3d(mesh.V.row(mesh.F(f, 0))).dot(
        Eigen::Vector3d(mesh.V.row(mesh.F(f, 1))).cross(Eigen::Vector3d(mesh.V.row(mesh.F(f, 2)))));
  return six_volume / 6.0;
}

TEST(FillHoles, ClosesSmallHolesWithOutwardNonDegenerateTriangles) {
  const TriMesh sphere = test::uv_sphere(50.0, 40, 60);
  ASSERT_TRUE(closed_and_oriented(sphere));
  // Three one-ring holes (about 10 mm across) far apart.
  TriMesh holed = test::without_faces_around(sphere, {2 + 10 * 60 + 5, 2 + 20 * 60 + 30, 2 + 30 * 60 + 50});
  ASSERT_EQ(test::boundary_loops_of(holed).size(), 3u);
  EXPECT_EQ(fill_holes(holed, 15.0).size(), 3u);
  EXPECT_TRUE(test::boundary_loops_of(holed).empty());
  EXPECT_TRUE(closed_and_oriented(holed));
  EXPECT_GT(triangle_areas(holed).minCoeff(), 1e-3);
  EXPECT_NEAR(enclosed_volume_mm3(holed), enclosed_volume_mm3(sphere), 0.002 * enclosed_volume_mm3(sphere));
}

TEST(FillHoles, LeavesHolesWiderThanTheLimitOpen) {
  const TriMesh sphere = test::uv_sphere(50.0, 40, 60);
  std::vector<int> band;  // a ring of vertices around the pole: a hole about 40 mm across
  for (int s = 0; s < 60; ++s) band.push_back(2 + 4 * 60 + s);
  band.push_back(0);
  for (int r = 1; r < 4; ++r)
    for (int s = 0; s < 60; ++s) band.push_back(2 + (r - 1) * 60 + s);
  TriMesh holed = test::without_faces_around(sphere, band);
  const auto faces_before = holed.F.rows();
  EXPECT_TRUE(fill_holes(holed, 15.0).empty());
  EXPECT_EQ(holed.F.rows(), faces_before);
  EXPECT_EQ(test::boundary_loops_of(holed).size(), 1u);
  const Eigen::Index vertices_before = holed.V.rows();
  const std::vector<HoleRepair> filled = fill_holes(holed, 60.0);
  ASSERT_EQ(filled.size(), 1u);
  EXPECT_GT(filled[0].across_mm, 30.0);  // "about 40 mm across"
  EXPECT_LT(filled[0].across_mm, 60.0);
  EXPECT_EQ(filled[0].patch_vertices, holed.V.rows() - vertices_before);
  EXPECT_FALSE(filled[0].fan);
  EXPECT_TRUE(closed_and_oriented(holed));
  EXPECT_GT(triangle_areas(holed).minCoeff(), 1e-3);
  // The patch is faired, not flat: its vertices stay near the sphere (a flat lid over this hole lies up
  // to 4.9 mm inside it at its centre).
  double worst_mm = 0.0;
  for (Eigen::Index v = vertices_before; v < holed.V.rows(); ++v)
    worst_mm = std::max(worst_mm, std::abs(holed.V.row(v).norm() - 50.0));
  EXPECT_LT(worst_mm, 1.0);
  std::printf("patch: %d vertices, farthest %.3f mm from the sphere\n", static_cast<int>(holed.V.rows() - vertices_before),
              worst_mm);
}

TEST(FillHoles, ClosesOnlyTheHolesWithinTheLimitWhenOthersAreJustLarger) {
  // Widening a ragged hole makes it a little larger than the scan's; a neighbouring loop only a little
  // larger than the limit must still stay open. One hole around one vertex, one around two neighbours.
  const TriMesh sphere = test::uv_sphere(50.0, 40, 60);
  TriMesh holed = test::without_faces_around(sphere, {2 + 10 * 60 + 5, 2 + 25 * 60 + 30, 2 + 25 * 60 + 31});
  const auto loops = test::boundary_loops_of(holed);
  ASSERT_EQ(loops.size(), 2u);
  double small_mm = loop_across_mm(holed.V, loops[0]), large_mm = loop_across_mm(holed.V, loops[1]);
  if (small_mm > large_mm) std::swap(small_mm, large_mm);
  const double limit_mm = 0.5 * (small_mm + large_mm);
  ASSERT_LT(large_mm, 1.25 * limit_mm);  // within the slack a trimmed hole may grow by
  const std::vector<HoleRepair> filled = fill_holes(holed, limit_mm);
  ASSERT_EQ(filled.size(), 1u);
  EXPECT_DOUBLE_EQ(filled[0].across_mm, small_mm);
  const auto left_open = test::boundary_loops_of(holed);
  ASSERT_EQ(left_open.size(), 1u);
  EXPECT_DOUBLE_EQ(loop_across_mm(holed.V, left_open[0]), large_mm);
}

TEST(FillHoles, MeasuresAHoleAcrossNotAround) {
  // A zig-zag loop: 12 points alternating between radius 6 and 3 mm, in a plane.
  Eigen::MatrixXd V(12, 3);
  std::vector<int> loop;
  for (int i = 0; i < 12; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / 12.0, radius = i % 2 == 0 ? 6.0 : 3.0;
    V.row(i) << radius * std::cos(angle), radius * std::sin(angle), 0.0;
    loop.push_back(i);
  }
  EXPECT_NEAR(loop_across_mm(V, loop), 12.0, 1e-12);  // points 0 and 6 are opposite on the outer circle
}

TEST(CutAlongZeroLevel, SplitsTrianglesExactlyOnThePlaneWithoutSlivers) {
  TriMesh sphere = test::uv_sphere(50.0, 30, 45);
  const double area_before = surface_area(sphere);
  const Eigen::Vector3d normal = Eigen::Vector3d(0.3, -0.2, 1.0).normalized();
  constexpr double kOffsetMm = 7.3;
  Eigen::MatrixXd fields(sphere.V.rows(), 2);
  fields.col(0) = (sphere.V * normal).array() - kOffsetMm;
  fields.col(1) = sphere.V.col(0);  // carried along: must stay linear in position
  cut_along_zero_level(sphere, fields, 0, 0.1);

  EXPECT_NEAR(surface_area(sphere), area_before, 1e-9 * area_before);
  EXPECT_TRUE(closed_and_oriented(sphere));
  EXPECT_EQ(test::euler_characteristic_of(sphere), 2);
  int on_cut = 0;
  for (Eigen::Index v = 0; v < sphere.V.rows(); ++v) {
    EXPECT_NEAR(fields(v, 1), sphere.V(v, 0), 1e-9);
    if (fields(v, 0) != 0.0) continue;
    ++on_cut;
    // Split vertices lie on the plane; snapped ones within a tenth of an edge (~ 0.7 mm) of it.
    EXPECT_NEAR(Eigen::Vector3d(sphere.V.row(v)).dot(normal) - kOffsetMm, 0.0, 0.75);
  }
  EXPECT_GT(on_cut, 45);
  const Eigen::VectorXd areas = triangle_areas(sphere);
  EXPECT_GT(areas.minCoeff(), 1e-3 * areas.mean()) << "sliver triangle";
  for (Eigen::Index f = 0; f < sphere.F.rows(); ++f) {
    const double lo = std::min({fields(sphere.F(f, 0), 0), fields(sphere.F(f, 1), 0), fields(sphere.F(f, 2), 0)});
    const double hi = std::max({fields(sphere.F(f, 0), 0), fields(sphere.F(f, 1), 0), fields(sphere.F(f, 2), 0)});
    EXPECT_FALSE(lo < 0.0 && hi > 0.0) << "face " << f << " still straddles the cut";
  }
}

}  // namespace
}  // namespace lastcut
