// Bijective ARAP: the outline filter (outline_clearance.hpp) and the barriers (boundary_barrier.hpp,
// fold_barrier.hpp: zero where nothing is near, infinite at contact, gradients against central
// differences) on hand-made polygons, and a helicoidal ramp whose near-isometric flattening must overlap
// itself, flattened with a simple outline.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "engine/flatten/arap_iterations.hpp"
#include "engine/flatten/boundary_barrier.hpp"
#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/flatten.hpp"
#include "engine/flatten/fold_barrier.hpp"
#include "engine/flatten/outline_clearance.hpp"
#include "engine/flatten/plane_rotation_start.hpp"
#include "tests/flatten/flatten_fixtures.hpp"

namespace lastcut {
namespace {

using testing::helicoidal_ramp;

Eigen::MatrixXd points(std::initializer_list<std::pair<double, double>> xy) {
  Eigen::MatrixXd UV(static_cast<Eigen::Index>(xy.size()), 2);
  Eigen::Index row = 0;
  for (const auto& [x, y] : xy) UV.row(row++) << x, y;
  return UV;
}

TEST(OutlineClearance, SquareIsSimpleAndBowTieCrosses) {
  const OutlineClearance outline({0, 1, 2, 3}, 0.1);
  EXPECT_FALSE(outline.crosses(points({{0, 0}, {10, 0}, {10, 10}, {0, 10}})));
  EXPECT_TRUE(outline.crosses(points({{0, 0}, {10, 0}, {0, 10}, {10, 10}})));
}

// A slit: the tip of a notch (vertex 4 at x = 5) approaches the opposite edge 0-1 (y = 0).
Eigen::MatrixXd notch(double tip_y_mm) {
  return points({{0, 0}, {10, 0}, {10, 10}, {6, 10}, {5, tip_y_mm}, {4, 10}, {0, 10}});
}

TEST(OutlineClearance, StepKeepsTheClearanceOrStopsShortOfIt) {
  const OutlineClearance outline({0, 1, 2, 3, 4, 5, 6}, 0.1);
  const Eigen::MatrixXd start = notch(5.0);
  EXPECT_TRUE(outline.keeps_clear(start, notch(0.2)));
  EXPECT_TRUE(outline.keeps_clear(start, notch(0.1001)));
  EXPECT_FALSE(outline.keeps_clear(start, notch(0.0999)));
  EXPECT_FALSE(outline.keeps_clear(start, notch(-1.0)));  // crossed
  EXPECT_TRUE(outline.crosses(notch(-1.0)));
  // A pair already closer than the clearance may narrow by at most half its gap, never touch.
  EXPECT_TRUE(outline.keeps_clear(notch(0.05), notch(0.06)));
  EXPECT_TRUE(outline.keeps_clear(notch(0.05), notch(0.0251)));
  EXPECT_FALSE(outline.keeps_clear(notch(0.05), notch(0.0249)));
  EXPECT_FALSE(outline.keeps_clear(notch(0.05), notch(0.0)));
  // Edge 0-1 against the notch's sides, 0.1 mm away: brute force gives the same distance.
  EXPECT_NEAR(outline.smallest_gap_mm(notch(0.1), 1), 0.1, 1e-12);
}

std::vector<double> drawn_lengths(const Eigen::MatrixXd& UV) {
  std::vector<double> arc(static_cast<size_t>(UV.rows()));
  for (Eigen::Index k = 0; k < UV.rows(); ++k) arc[static_cast<size_t>(k)] = (UV.row((k + 1) % UV.rows()) - UV.row(k)).norm();
  return arc;
}

// Central differences of energy(UV) against the analytic gradient, every coordinate.
template <typename Energy>
void expect_gradient_matches(const Eigen::MatrixXd& UV, Energy energy) {
  std::vector<double> gradient(2 * static_cast<size_t>(UV.rows()), 0.0);
  energy(UV, &gradient);
  constexpr double kStep = 1e-6;
  for (Eigen::Index v = 0; v < UV.rows(); ++v) {
    for (int c = 0; c < 2; ++c) {
      Eigen::MatrixXd plus = UV, minus = UV;
      plus(v, c) += kStep;
      minus(v, c) -= kStep;
      const double numeric = (energy(plus, nullptr) - energy(minus, nullptr)) / (2 * kStep);
      EXPECT_NEAR(gradient[2 * static_cast<size_t>(v) + c], numeric, 1e-5 * (1.0 + std::abs(numeric)))
          << "vertex " << v << " coordinate " << c;
    }
  }
}

TEST(BoundaryBarrier, ZeroFarAwayGrowingNearAndInfiniteAtContact) {
  const std::vector<int> loop = {0, 1, 2, 3, 4, 5, 6};
  BoundaryBarrierOptions options;  // reach 1 mm
  const BoundaryBarrier barrier(loop, drawn_lengths(notch(5.0)), options);
  EXPECT_EQ(barrier.energy(notch(5.0)), 0.0);
  EXPECT_EQ(barrier.active_pairs(notch(5.0)), 0);
  // Tip against edge 0-1 only: lambda (1 / d - 1)^2 with lambda = 1 mm^2.
  EXPECT_NEAR(barrier.energy(notch(0.5)), 1.0, 1e-12);
  EXPECT_NEAR(barrier.energy(notch(0.25)), 9.0, 1e-12);
  EXPECT_EQ(barrier.active_pairs(notch(0.25)), 1);
  EXPECT_TRUE(std::isinf(barrier.energy(notch(0.0))));
}

TEST(BoundaryBarrier, GradientMatchesDifferences) {
  const std::vector<int> loop = {0, 1, 2, 3, 4, 5, 6};
  const BoundaryBarrier barrier(loop, drawn_lengths(notch(5.0)), BoundaryBarrierOptions{});
  Eigen::MatrixXd UV = notch(0.4);
  UV(4, 0) = 3.3;  // the tip off the middle of the edge, so t is not 1/2
  expect_gradient_matches(UV, [&](const Eigen::MatrixXd& X, std::vector<double>* g) { return barrier.energy(X, g); });
}

TEST(FoldBarrier, ZeroForHealthyTrianglesAndGradientMatchesForThinOnes) {
  const TriMesh mesh = testing::square_10mm();
  const TriangleFrames frames = compute_triangle_frames(mesh);
  Eigen::MatrixXd UV = mesh.V.leftCols(2);
  const FoldBarrier barrier(frames, UV);
  EXPECT_EQ(barrier.energy(UV), 0.0);
  // Vertex 1 pulled near the diagonal 0-2 squeezes triangle 0 to 9 % of its area.
  Eigen::MatrixXd thin = UV;
  thin.row(1) << 5.5, 4.6;
  EXPECT_GT(barrier.energy(thin), 0.0);
  expect_gradient_matches(thin, [&](const Eigen::MatrixXd& X, std::vector<double>* g) { return barrier.energy(X, g); });
  Eigen::MatrixXd folded = UV;
  folded.row(1) << 4.0, 6.0;  // across the diagonal 0-2: triangle 0 flips
  EXPECT_TRUE(std::isinf(barrier.energy(folded)));
}

TEST(InjectiveArap, HelicoidalRampFlattensWithASimpleOutline) {
  const TriMesh ramp = helicoidal_ramp(40.0, 80.0, 420.0, 20.0, 10, 240);
  const MeshTopology topology = check_disk(ramp);
  const OutlineClearance outline(topology.boundary_loops[0], 0.1);

  // The premise: plain ARAP lays the ramp out overlapping itself.
  FlattenOptions plain;
  plain.injective_outline = false;
  const FlattenResult overlapping = flatten(ramp, topology, plain);
  ASSERT_TRUE(outline.crosses(overlapping.UV));
  ASSERT_EQ(outline.smallest_gap_mm(overlapping.UV, 1), 0.0);

  FlattenOptions options;
  options.max_iterations = 600;  // from the Tutte ellipse the ramp needs ~400 until its ends meet
  const FlattenResult result = flatten(ramp, topology, options);
  EXPECT_FALSE(outline.crosses(result.UV));
  // Brute force over all pairs sharing no vertex: at least the clearance apart.
  const double gap_mm = outline.smallest_gap_mm(result.UV, 1);
  EXPECT_GE(gap_mm, 0.1 * (1.0 - 1e-9));
  // The ends met: the boundary barrier, not the iteration limit, kept them apart.
  EXPECT_LE(gap_mm, options.barrier_reach_mm);
  EXPECT_EQ(result.flipped_triangles, 0);
  EXPECT_TRUE(result.converged) << "bijective ARAP converges where the outline meets itself";
  ASSERT_FALSE(result.notes.empty());
  EXPECT_NE(result.notes.back().find("reran bijective ARAP"), std::string::npos) << result.notes.back();

  const DistortionMeasures d = measure_distortion(ramp, result.UV, topology);
  const DistortionMeasures d_plain = measure_distortion(ramp, overlapping.UV, topology);
  EXPECT_EQ(d.flipped_triangles, 0);
  EXPECT_TRUE(std::isfinite(d.D_angle) && std::isfinite(d.D_area));
  // The slit costs distortion: more than the overlapping near-isometry, yet far from the Tutte ellipse's.
  EXPECT_GT(d.D_angle, d_plain.D_angle);
  EXPECT_LT(d.D_angle, 2.5);
  std::cout << "ramp (" << ramp.triangle_count() << " triangles): plain D_angle " << d_plain.D_angle << " D_area "
            << d_plain.D_area << "; injective D_angle " << d.D_angle << " D_area " << d.D_area << ", "
            << result.iterations << " iterations, smallest gap " << gap_mm << " mm; " << result.notes.back() << "\n";
}

// An unguarded run watching its outline stops once the outline has crossed itself 8 iterations in a row
// (flatten.cpp then reruns injectively), and up to there its iterates are those of the run that does not
// watch: the same map, bit for bit, after as many iterations.
TEST(InjectiveArap, AnUnguardedRunGivesUpOnAnOutlineThatStaysCrossed) {
  const TriMesh ramp = helicoidal_ramp(40.0, 80.0, 420.0, 20.0, 10, 240);
  const MeshTopology topology = check_disk(ramp);
  const OutlineClearance outline(topology.boundary_loops[0], 0.1);
  const TriangleFrames frames = compute_triangle_frames(ramp);
  const ReducedLaplacian laplacian = pinned_cotangent_laplacian(frames, topology);
  SparseCholesky factor;
  factor.analyze_pattern(laplacian.matrix);
  factor.factorize(laplacian.matrix);
  const std::optional<Eigen::MatrixXd> plane = plane_rotation_start(ramp, frames, topology, laplacian, factor);
  ASSERT_TRUE(plane.has_value());
  const Eigen::MatrixXd start = *plane;
  constexpr int kMaxIterations = 600;
  constexpr double kTolerance = 1e-6;

  Eigen::MatrixXd unwatched = start;
  const ArapIterationReport full = run_arap_iterations(frames, laplacian, factor, unwatched, kMaxIterations, kTolerance, false);
  ASSERT_TRUE(outline.crosses(unwatched)) << "the premise: the plain run ends crossed";

  Eigen::MatrixXd watched = start;
  const ArapIterationReport gave_up =
      run_arap_iterations(frames, laplacian, factor, watched, kMaxIterations, kTolerance, false, true, &outline, 8);
  EXPECT_TRUE(gave_up.gave_up_crossed);
  EXPECT_GE(gave_up.iterations, 8);
  EXPECT_LT(gave_up.iterations, full.iterations);
  EXPECT_TRUE(outline.crosses(watched));

  Eigen::MatrixXd same_count = start;
  run_arap_iterations(frames, laplacian, factor, same_count, gave_up.iterations, kTolerance, false);
  EXPECT_TRUE(same_count == watched) << "the watch changed the iterates";
  std::cout << "ramp: the plain run takes " << full.iterations << " iterations, the watched one gives up after "
            << gave_up.iterations << "\n";
}

}  // namespace
}  // namespace lastcut
