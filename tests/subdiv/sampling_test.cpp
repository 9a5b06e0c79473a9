// Any detail n: exact counts, a watertight result, and every sample on the patches of every face
// that uses it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <iostream>
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

// Mean of l_1 / mean(l) over the control edges' ends at valence-3 vertices: l_1 the sample segment at
// the vertex.
double first_segment_ratio_at_valence_3(const QuadMesh& control, const SubdividedSurface& surface, int n) {
  const QuadTopology topology = build_quad_topology(control);
  double sum = 0.0;
  int count = 0;
  for (const EdgeEndSpacing& edge : edge_end_spacing(control, surface, n)) {
    if (topology.valence(edge.from) == 3) sum += edge.first_ratio, ++count;
    if (topology.valence(edge.to) == 3) sum += edge.last_ratio, ++count;
  }
  EXPECT_EQ(count, 24);  // 8 corners x 3 edges
  return sum / count;
}

TEST(BezierSampling, EvenSpreadLengthensTheCrampedSegmentsAtExtraordinaryVerticesAndStaysWelded) {
  const QuadMesh control = test::cube_sphere(3, 25.0);
  const QuadTopology topology = build_quad_topology(control);
  const std::vector<BezierPatch> patches = build_bezier_patches(control, topology);
  const int n = 5;
  const SubdividedSurface uniform = subdivide_bezier(control, n);
  const SubdividedSurface even = subdivide_bezier(control, n, SampleSpread::EvenAtExtraordinary);
  EXPECT_EQ(even.quads.Q, uniform.quads.Q);  // same connectivity: still welded and watertight
  const double uniform_ratio = first_segment_ratio_at_valence_3(control, uniform, n);
  const double even_ratio = first_segment_ratio_at_valence_3(control, even, n);
  std::cout << "l_1 / mean at valence 3, n = 5: uniform " << uniform_ratio << ", even " << even_ratio << "\n";
  EXPECT_LT(uniform_ratio, 0.92);
  EXPECT_NEAR(even_ratio, 1.0, 0.04);
  // Every sample on its face's patch at the (warped) parameters it reports, and inside the face.
  int moved = 0;
  for (int v = 0; v < even.quads.vertex_count(); ++v) {
    const Eigen::Vector2d uv = even.source_uv.row(v).transpose();
    EXPECT_TRUE(uv.minCoeff() >= 0.0 && uv.maxCoeff() <= 1.0);
    const Eigen::Vector3d on_patch = patch_position(patches[static_cast<size_t>(even.source_face[static_cast<size_t>(v)])], uv.x(), uv.y());
    EXPECT_LT((even.quads.V.row(v).transpose() - on_patch).norm(), 1e-12);
    moved += (uv - uniform.source_uv.row(v).transpose()).norm() > 1e-9;
  }
  // Only the samples of faces at the eight corners move (3 faces each, (n + 1)^2 - 2n - 1 samples off
  // the face's far edges, minus the corner itself).
  EXPECT_GT(moved, 0);
  EXPECT_LE(moved, 8 * 3 * (n * n - 1));
}

TEST(BezierSampling, EdgeEndSpacingIsOneWhereAPlaneIsSampledEvenly) {
  // A flat regular grid: where a face's whole 4 x 4 neighbourhood is regular its patch is the affine
  // map of the parameters, so the uniform samples along an interior edge are exactly evenly spaced.
  QuadMesh control = test::height_grid(6, 6, 3);
  control.V.col(2).setZero();
  const int n = 5;
  int checked = 0;
  for (const EdgeEndSpacing& edge : edge_end_spacing(control, subdivide_bezier(control, n), n)) {
    const Eigen::Vector3d a = control.V.row(edge.from).transpose(), b = control.V.row(edge.to).transpose();
    EXPECT_NEAR((a - b).norm(), 1.0, 1e-12);  // from and to are the edge's ends
    if (a.head<2>().minCoeff() < 2 || a.head<2>().maxCoeff() > 4 || b.head<2>().minCoeff() < 2 || b.head<2>().maxCoeff() > 4) continue;
    EXPECT_NEAR(edge.first_ratio, 1.0, 1e-12);
    EXPECT_NEAR(edge.last_ratio, 1.0, 1e-12);
    ++checked;
  }
  EXPECT_EQ(checked, 12);  // the 3 x 3 vertices of [2, 4]^2: 2 x 3 x 2 edges
}

TEST(BezierSampling, EdgeEndSpacingSkipsControlVerticesNoFaceUses) {
  // The same sphere with an unused vertex in front: the output ids of corners and edge samples move,
  // the spacing must not.
  const QuadMesh control = test::cube_sphere(3, 25.0);
  QuadMesh padded;
  padded.V.resize(control.vertex_count() + 1, 3);
  padded.V.row(0) << 1e3, 1e3, 1e3;
  padded.V.bottomRows(control.vertex_count()) = control.V;
  padded.Q = control.Q.array() + 1;
  const int n = 4;
  const auto plain = edge_end_spacing(control, subdivide_bezier(control, n, SampleSpread::EvenAtExtraordinary), n);
  const auto shifted = edge_end_spacing(padded, subdivide_bezier(padded, n, SampleSpread::EvenAtExtraordinary), n);
  ASSERT_EQ(plain.size(), shifted.size());
  for (size_t e = 0; e < plain.size(); ++e) {
    EXPECT_EQ(shifted[e].from, plain[e].from + 1);
    EXPECT_EQ(shifted[e].to, plain[e].to + 1);
    EXPECT_NEAR(shifted[e].first_ratio, plain[e].first_ratio, 1e-12);
    EXPECT_NEAR(shifted[e].last_ratio, plain[e].last_ratio, 1e-12);
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
