// The Bezier surface of a regular control grid is the uniform bicubic B-spline surface: C2 across
// every interior patch edge (positions and first and second derivatives agree), and each patch equals
// the B-spline evaluated directly from its 4 x 4 control points.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>

#include "engine/subdiv/bezier_patches.hpp"
#include "tests/subdiv/quad_test_meshes.hpp"

namespace lastcut {
namespace {

constexpr int kGrid = 8;

void expect_near(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tolerance, const char* what) {
  EXPECT_LT((a - b).norm(), tolerance) << what << ": " << a.transpose() << " vs " << b.transpose();
}

void expect_same_jet(const PatchPoint& a, const PatchPoint& b) {
  expect_near(a.position, b.position, 1e-9, "position");
  expect_near(a.du, b.du, 1e-9, "d/du");
  expect_near(a.dv, b.dv, 1e-9, "d/dv");
  expect_near(a.duu, b.duu, 1e-9, "d2/du2");
  expect_near(a.duv, b.duv, 1e-9, "d2/dudv");
  expect_near(a.dvv, b.dvv, 1e-9, "d2/dv2");
}

TEST(BezierContinuity, RegularGridIsC2AcrossEveryInteriorPatchEdge) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    const QuadMesh grid = test::height_grid(kGrid, kGrid, seed);
    const std::vector<BezierPatch> patches = build_bezier_patches(grid, build_quad_topology(grid));
    int edges = 0;
    for (int j = 0; j < kGrid; ++j) {
      for (int i = 0; i < kGrid; ++i) {
        const BezierPatch& here = patches[static_cast<size_t>(i + kGrid * j)];
        for (double t : {0.0, 0.13, 0.5, 0.77, 1.0}) {
          if (i + 1 < kGrid) expect_same_jet(evaluate_patch(here, 1.0, t), evaluate_patch(patches[static_cast<size_t>(i + 1 + kGrid * j)], 0.0, t));
          if (j + 1 < kGrid) expect_same_jet(evaluate_patch(here, t, 1.0), evaluate_patch(patches[static_cast<size_t>(i + kGrid * (j + 1))], t, 0.0));
        }
        edges += (i + 1 < kGrid) + (j + 1 < kGrid);
      }
    }
    EXPECT_EQ(edges, 2 * kGrid * (kGrid - 1));
    // The heights really vary, so matching derivatives mean something.
    EXPECT_GT(grid.V.col(2).maxCoeff() - grid.V.col(2).minCoeff(), 1.0);
  }
}

// Uniform cubic B-spline basis and derivatives at t in [0, 1] (de Boor, A Practical Guide to Splines).
std::array<std::array<double, 4>, 3> bspline_basis(double t) {
  const double s = 1.0 - t;
  return {{{s * s * s / 6.0, (3 * t * t * t - 6 * t * t + 4) / 6.0, (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6.0, t * t * t / 6.0},
           {-s * s / 2.0, (9 * t * t - 12 * t) / 6.0, (-9 * t * t + 6 * t + 3) / 6.0, t * t / 2.0},
           {s, 3 * t - 2, -3 * t + 1, t}}};
}

TEST(BezierContinuity, InteriorPatchesEqualTheDirectBSpline) {
  const QuadMesh grid = test::height_grid(kGrid, kGrid, 7);
  const std::vector<BezierPatch> patches = build_bezier_patches(grid, build_quad_topology(grid));
  const auto control = [&grid](int i, int j) -> Eigen::Vector3d { return grid.V.row(i + (kGrid + 1) * j).transpose(); };
  for (int j = 1; j + 1 < kGrid; ++j) {
    for (int i = 1; i + 1 < kGrid; ++i) {
      for (double u : {0.0, 0.3, 1.0}) {
        for (double v : {0.0, 0.6, 1.0}) {
          const auto bu = bspline_basis(u), bv = bspline_basis(v);
          PatchPoint direct{};
          direct.position = direct.du = direct.dv = direct.duu = direct.duv = direct.dvv = Eigen::Vector3d::Zero();
          for (int b = 0; b < 4; ++b) {
            for (int a = 0; a < 4; ++a) {
              const Eigen::Vector3d p = control(i - 1 + a, j - 1 + b);
              direct.position += bu[0][a] * bv[0][b] * p;
              direct.du += bu[1][a] * bv[0][b] * p;
              direct.dv += bu[0][a] * bv[1][b] * p;
              direct.duu += bu[2][a] * bv[0][b] * p;
              direct.duv += bu[1][a] * bv[1][b] * p;
              direct.dvv += bu[0][a] * bv[2][b] * p;
            }
          }
          expect_same_jet(evaluate_patch(patches[static_cast<size_t>(i + kGrid * j)], u, v), direct);
        }
      }
    }
  }
}

TEST(BezierContinuity, ExtraordinaryVertexPatchesMeetInOnePointWithOneTangentPlane) {
  const QuadMesh sphere = test::cube_sphere(3, 20.0);
  const QuadTopology topology = build_quad_topology(sphere);
  const std::vector<BezierPatch> patches = build_bezier_patches(sphere, topology);
  int checked = 0;
  for (int v = 0; v < sphere.vertex_count(); ++v) {
    if (topology.valence(v) != 3) continue;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    std::vector<PatchPoint> corners;
    for (int j = 0; j < topology.faces_at(v); ++j) {
      const int h = topology.half_edge_at(v, j);
      const double u = (h % 4 == 1 || h % 4 == 2) ? 1.0 : 0.0, w = (h % 4 >= 2) ? 1.0 : 0.0;
      corners.push_back(evaluate_patch(patches[static_cast<size_t>(h / 4)], u, w));
      if (j == 0) normal = corners.back().du.cross(corners.back().dv).normalized();
    }
    for (const PatchPoint& corner : corners) {
      expect_near(corner.position, corners.front().position, 1e-12, "corner");
      EXPECT_LT(std::abs(corner.du.normalized().dot(normal)), 1e-12);
      EXPECT_LT(std::abs(corner.dv.normalized().dot(normal)), 1e-12);
    }
    ++checked;
  }
  EXPECT_EQ(checked, 8);
}

}  // namespace
}  // namespace lastcut
