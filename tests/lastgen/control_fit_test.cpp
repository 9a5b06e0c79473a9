// fit_control_least_squares (engine/lastgen/control_fit.hpp) on a case with an exact answer: a wobbly
// open grid fitted to a plane. Every Bezier point is an affine combination of control points and the
// fairness term of a flat net lies in its plane, so the fitted surface is the plane itself.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/lastgen/control_fit.hpp"
#include "engine/subdiv/bezier_patches.hpp"

namespace lastcut {
namespace {

constexpr int kCellsX = 8, kCellsY = 6;
constexpr double kCellMm = 10.0;

QuadMesh wobbly_grid() {
  QuadMesh grid;
  grid.V.resize((kCellsX + 1) * (kCellsY + 1), 3);
  for (int j = 0; j <= kCellsY; ++j) {
    for (int i = 0; i <= kCellsX; ++i) {
      grid.V.row(i + (kCellsX + 1) * j) << kCellMm * i + 0.7 * std::sin(1.3 * j), kCellMm * j + 0.5 * std::cos(0.9 * i),
          2.0 * std::sin(0.8 * i) * std::cos(1.1 * j);
    }
  }
  grid.Q.resize(kCellsX * kCellsY, 4);
  for (int j = 0; j < kCellsY; ++j) {
    for (int i = 0; i < kCellsX; ++i) {
      const int a = i + (kCellsX + 1) * j;
      grid.Q.row(i + kCellsX * j) << a, a + 1, a + kCellsX + 2, a + kCellsX + 1;
    }
  }
  return grid;
}

TEST(ControlFit, AGridFittedToAPlaneBecomesThatPlane) {
  const Eigen::Vector3d normal = Eigen::Vector3d(-0.3, -0.2, 1.0).normalized();
  const Eigen::Vector3d origin(0.0, 0.0, 4.0);
  const auto height = [&](const Eigen::Vector3d& p) { return (p - origin).dot(normal); };
  const auto onto_plane = [&](const Eigen::Vector3d& p) -> Eigen::Vector3d { return p - height(p) * normal; };
  QuadMesh grid = wobbly_grid();
  const QuadTopology topology = build_quad_topology(grid);
  const auto surface_error = [&]() {
    const std::vector<BezierPatch> patches = build_bezier_patches(grid, topology);
    double worst = 0.0;
    for (const BezierPatch& patch : patches) {
      for (double u : {0.0, 0.21, 0.5, 0.83, 1.0}) {
        for (double v : {0.0, 0.37, 0.64, 1.0}) worst = std::max(worst, std::abs(height(patch_position(patch, u, v))));
      }
    }
    return worst;
  };
  EXPECT_GT(surface_error(), 1.0);
  ControlFitTargets targets;
  targets.onto_surface = onto_plane;
  targets.onto_rim = onto_plane;
  targets.weight = [](const Eigen::Vector3d&, const Eigen::Vector3d& foot) { return foot.x() < 20.0 ? 10.0 : 1.0; };
  fit_control_least_squares(grid, topology, targets, ControlFitOptions{});
  EXPECT_LT(surface_error(), 1e-9);
}

}  // namespace
}  // namespace lastcut
