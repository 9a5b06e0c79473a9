// Any detail n: exact counts, a watertight result, and every sample on the patches of every face
// that uses it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>
#include <utility>

#include "engine/subdiv/sample_surface.hpp"
#include "tests/subdiv/quad_test_meshes.hpp"

namespace lastcut {
namespace {

TEST(BezierSampling, OddDetailsGiveExactCountsAndAWatertightSurfaceOnThePatches) {
  const QuadMesh control = test::cube_sphere(3, 25.0);
  const long long F = control.quad_count(), V = control.vertex_count(), E = 2 * F;  // closed quad mesh: 4F = 2E
  ASSERT_EQ(V - E + F, 2);
  const QuadTopology topology = build_quad_topology(control);
  const std::vector<BezierPatch> patches = build_bezier_patches(control, topology);
  for (int n : {3, 5, 7}) {
    const SubdividedSurface surface = subdivide_bezier(control, n);
    const QuadMesh& out = surface.quads;
    EXPECT_EQ(out.quad_count(), F * n * n);
    EXPECT_EQ(out.vertex_count(), V + E * (n - 1) + F * (n - 1) * (n - 1));
    // Watertight and consistently oriented: each directed edge once, its reverse once.
    std::map<std::pair<int, int>, int> directed;
    for (int q = 0; q < out.quad_count(); ++q) {
      for (int k = 0; k < 4; ++k) ++directed[{out.Q(q, k), out.Q(q, (k + 1) % 4)}];
    }
    for (const auto& [edge, count] : directed) {
      ASSERT_EQ(count, 1) << "n = " << n;
      ASSERT_EQ(directed.count({edge.second, edge.first}), 1u) << "n = " << n << ": open edge";
    }
    EXPECT_EQ(static_cast<long long>(directed.size()), 4 * F * n * n);
    EXPECT_EQ(out.vertex_count() - 2 * F * n * n + out.quad_count(), 2);  // Euler: still a sphere
    // Output quad i + n j of face q has corners at grid points (i,j), (i+1,j), (i+1,j+1), (i,j+1):
    // every corner must be that face's patch at (i/n, j/n), whichever face computed the vertex.
    double worst_mm = 0.0;
    for (int q = 0; q < out.quad_count(); ++q) {
      const int face = q / (n * n), i = q % (n * n) % n, j = q % (n * n) / n;
      const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
      for (int k = 0; k < 4; ++k) {
        const Eigen::Vector3d expected =
            evaluate_patch(patches[static_cast<size_t>(face)], static_cast<double>(i + di[k]) / n, static_cast<double>(j + dj[k]) / n).position;
        worst_mm = std::max(worst_mm, (out.V.row(out.Q(q, k)).transpose() - expected).norm());
      }
    }
    EXPECT_LT(worst_mm, 1e-11) << "n = " << n;
  }
}

TEST(BezierSampling, DetailOneReturnsTheLimitCornersOnTheControlConnectivity) {
  const QuadMesh control = test::height_grid(4, 3, 5);
  const SubdividedSurface surface = subdivide_bezier(control, 1);
  EXPECT_EQ(surface.quads.Q, control.Q);
  EXPECT_EQ(surface.quads.vertex_count(), control.vertex_count());
}

TEST(BezierSampling, TriangulationKeepsVerticesAndSplitsEachQuad) {
  const SubdividedSurface surface = subdivide_bezier(test::cube_sphere(2, 10.0), 3);
  const TriMesh mesh = triangulate_quads(surface.quads);
  EXPECT_EQ(mesh.triangle_count(), 2 * surface.quads.quad_count());
  EXPECT_EQ(mesh.V, surface.quads.V);
  // Outward: the enclosed signed volume is positive and near the wobbly sphere's (> half a 10 mm ball).
  double volume = 0.0;
  for (int f = 0; f < mesh.triangle_count(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    volume += a.dot(b.cross(c)) / 6.0;
  }
  EXPECT_GT(volume, 0.8 * 4.0 / 3.0 * 3.14159 * 1000.0 * 0.5);
}

}  // namespace
}  // namespace lastcut
