// lastgen's Bezier path (LastParams::surface = LastSurface::Bezier): the quad control mesh of the
// last interpolates the solid at its limit corners, and the generated last is closed, outward,
// the asked triangle count, the asked size, and the same for the same parameters.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/lastgen/generate_last.hpp"
#include "engine/lastgen/last_control_mesh.hpp"
#include "engine/subdiv/sample_surface.hpp"
#include "tests/lastgen/mesh_checks.hpp"

namespace lastcut {
namespace {

LastParams bezier_params(int triangles) {
  LastParams params = LastParams::for_eu_size(42, FootSide::Right);
  params.target_triangles = triangles;
  params.surface = LastSurface::Bezier;
  return params;
}

TEST(BezierLast, ControlMeshLimitCornersLieOnTheSolid) {
  const LastParams params = bezier_params(20000);
  const LastShape shape(params);
  const QuadMesh control = last_control_mesh(shape, params, 800);
  EXPECT_NEAR(control.quad_count(), 800, 80);
  const QuadTopology topology = build_quad_topology(control);  // closed 2-manifold or it throws
  int extraordinary = 0;
  for (int v = 0; v < control.vertex_count(); ++v) {
    EXPECT_FALSE(topology.on_boundary[static_cast<size_t>(v)]);
    extraordinary += topology.valence(v) != 4;
  }
  EXPECT_EQ(extraordinary, 8);
  const Eigen::MatrixXd corners = subdivide_bezier(control, 1).quads.V;
  double worst_mm = 0.0;
  for (Eigen::Index v = 0; v < corners.rows(); ++v) worst_mm = std::max(worst_mm, std::abs(shape.value(corners.row(v).transpose())));
  EXPECT_LT(worst_mm, 0.05);
}

TEST(BezierLast, GeneratedLastIsClosedOutwardAndTheAskedSize) {
  for (int triangles : {5000, 50000}) {
    const LastParams params = bezier_params(triangles);
    const GeneratedLast last = generate_last(params);
    EXPECT_EQ(last.mesh.triangle_count(), triangles);
    const test::EdgeCensus census = test::edge_census(last.mesh);
    EXPECT_EQ(census.boundary_edges, 0);
    EXPECT_EQ(census.non_manifold_edges, 0);
    EXPECT_EQ(census.inconsistent_edges, 0);
    EXPECT_EQ(test::euler_characteristic(last.mesh), 2);
    EXPECT_GT(test::signed_volume_mm3(last.mesh), 0.0);
    const Eigen::Vector3d size = bounding_box_size(last.mesh);
    EXPECT_NEAR(size.x(), params.length_mm, 2.0);
    EXPECT_NEAR(size.y(), params.ball_width_mm, 6.0);
    EXPECT_EQ(generate_last(params).mesh.V, last.mesh.V);
  }
}

}  // namespace
}  // namespace lastcut
