// Injective ARAP (outline_clearance.hpp): the outline filter on hand-made polygons, and a helicoidal ramp
// whose near-isometric flattening must overlap itself, flattened with a simple outline.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <string>

#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/flatten.hpp"
#include "engine/flatten/outline_clearance.hpp"

namespace lastcut {
namespace {

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

// A sector of an annulus (radii r_in..r_out) over sweep_deg > 360, lifted along z by pitch_mm per turn: a
// disk-topology ramp whose metric is close to flat (ds^2 = dr^2 + (r^2 + h^2) dtheta^2 with h = pitch / 2 pi,
// h/r_in = 0.08), so its near-isometric flattening is an annulus sector that overlaps itself by
// sweep - 360 degrees. Quads split along alternating diagonals, counter-clockwise seen from above.
TriMesh helicoidal_ramp(double r_in_mm, double r_out_mm, double sweep_deg, double pitch_mm, int radial, int around) {
  TriMesh mesh;
  mesh.V.resize((radial + 1) * (around + 1), 3);
  const double sweep_rad = sweep_deg * std::numbers::pi / 180.0;
  for (int j = 0; j <= around; ++j) {
    const double theta = sweep_rad * j / around;
    for (int i = 0; i <= radial; ++i) {
      const double r = r_in_mm + (r_out_mm - r_in_mm) * i / radial;
      mesh.V.row(j * (radial + 1) + i) << r * std::cos(theta), r * std::sin(theta),
          pitch_mm * theta / (2.0 * std::numbers::pi);
    }
  }
  mesh.F.resize(2 * radial * around, 3);
  int f = 0;
  for (int j = 0; j < around; ++j) {
    for (int i = 0; i < radial; ++i) {
      const int a = j * (radial + 1) + i, b = a + 1, c = a + radial + 2, d = a + radial + 1;
      if ((i + j) % 2 == 0) {
        mesh.F.row(f++) << a, b, c;
        mesh.F.row(f++) << a, c, d;
      } else {
        mesh.F.row(f++) << a, b, d;
        mesh.F.row(f++) << b, c, d;
      }
    }
  }
  return mesh;
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
  EXPECT_LE(gap_mm, 0.2);  // the ends met: it was the filter, not the iteration limit, that kept them apart
  EXPECT_EQ(result.flipped_triangles, 0);
  ASSERT_FALSE(result.notes.empty());
  EXPECT_NE(result.notes.back().find("reran injective ARAP"), std::string::npos) << result.notes.back();

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

}  // namespace
}  // namespace lastcut
