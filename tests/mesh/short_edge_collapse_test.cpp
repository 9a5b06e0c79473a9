// Short edges collapsed out of a cut mesh (engine/mesh/short_edge_collapse.hpp): a 10 mm square fanned
// round its centre, with crumbs a cut would leave on its outline, 4 um edges. The crumbs go, the square
// keeps its area and its one outline, and a corner next to a crumb stays exactly where it was.
#include <gtest/gtest.h>

#include "engine/core/mesh_topology.hpp"
#include "engine/mesh/short_edge_collapse.hpp"

namespace lastcut {
namespace {

// The square (0,0)-(10,10) in z = 0 as a fan round (5, 5) through the outline points given counter-clockwise.
TriMesh fan_square(const std::vector<Eigen::Vector2d>& outline) {
  TriMesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(outline.size()) + 1, 3);
  for (std::size_t i = 0; i < outline.size(); ++i) mesh.V.row(static_cast<Eigen::Index>(i)) << outline[i].x(), outline[i].y(), 0;
  const int centre = static_cast<int>(outline.size());
  mesh.V.row(centre) << 5, 5, 0;
  mesh.F.resize(static_cast<Eigen::Index>(outline.size()), 3);
  for (int i = 0; i < centre; ++i) mesh.F.row(i) << i, (i + 1) % centre, centre;
  return mesh;
}

double shortest_edge_mm(const TriMesh& mesh) {
  double shortest = INFINITY;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) shortest = std::min(shortest, (mesh.V.row(mesh.F(f, k)) - mesh.V.row(mesh.F(f, (k + 1) % 3))).norm());
  return shortest;
}

bool has_vertex_at(const TriMesh& mesh, const Eigen::Vector3d& p) {
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    if ((mesh.V.row(v).transpose() - p).norm() == 0) return true;
  return false;
}

TEST(ShortEdgeCollapse, CrumbsOnTheOutlineGoAndCornersStay) {
  TriMesh mesh = fan_square({{0, 0}, {5, 0}, {5.004, 0}, {9.996, 0}, {10, 0}, {10, 10}, {0, 10}});
  ASSERT_DOUBLE_EQ(surface_area(mesh), 100);
  EXPECT_EQ(collapse_short_edges(mesh, 0.01), 2);
  EXPECT_EQ(mesh.F.rows(), 5);
  EXPECT_GE(shortest_edge_mm(mesh), 0.01);
  EXPECT_NEAR(surface_area(mesh), 100, 1e-9);
  EXPECT_TRUE(has_vertex_at(mesh, {10, 0, 0})) << "the corner moved";
  const MeshTopology topology = build_mesh_topology(mesh.F, mesh.V.rows());
  EXPECT_EQ(topology.boundary_loops.size(), 1u);
  EXPECT_EQ(topology.boundary_loops.front().size(), 5u);
}

TEST(ShortEdgeCollapse, AMeshWithoutShortEdgesIsLeftAsItIs) {
  TriMesh mesh = fan_square({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  const TriMesh before = mesh;
  EXPECT_EQ(collapse_short_edges(mesh, 0.01), 0);
  EXPECT_EQ(mesh.V, before.V);
  EXPECT_EQ(mesh.F, before.F);
}

}  // namespace
}  // namespace lastcut
