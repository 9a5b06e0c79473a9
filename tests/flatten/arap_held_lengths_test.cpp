// ARAP with held edge lengths (engine/flatten/arap_held_lengths.hpp): on a spherical cap, which no
// flattening keeps isometric, plain ARAP shortens the rim; holding the rim's edges gives it back its 3D
// length, edge by edge, with no fold. On a developable patch there is nothing to correct: the exact
// development stays as it is.
#include <gtest/gtest.h>

#include "engine/core/mesh_topology.hpp"
#include "engine/flatten/arap_held_lengths.hpp"
#include "engine/flatten/distortion.hpp"
#include "engine/flatten/flatten.hpp"
#include "tests/flatten/flatten_fixtures.hpp"

namespace lastcut {
namespace {

std::vector<std::array<int, 2>> rim_edges(const MeshTopology& topology, std::size_t first, std::size_t count) {
  const std::vector<int>& loop = topology.boundary_loops.front();
  std::vector<std::array<int, 2>> edges;
  for (std::size_t i = first; i < first + count; ++i) edges.push_back({loop[i % loop.size()], loop[(i + 1) % loop.size()]});
  return edges;
}

double length_mm(const Eigen::MatrixXd& points, const std::vector<std::array<int, 2>>& edges) {
  double total = 0;
  for (const auto& [a, b] : edges) total += (points.row(b) - points.row(a)).norm();
  return total;
}

double worst_edge_change(const TriMesh& mesh, const Eigen::MatrixXd& UV, const std::vector<std::array<int, 2>>& edges) {
  double worst = 0;
  for (const auto& [a, b] : edges) {
    const double flat = (UV.row(b) - UV.row(a)).norm(), on_surface = (mesh.V.row(b) - mesh.V.row(a)).norm();
    worst = std::max(worst, std::abs(flat - on_surface) / on_surface);
  }
  return worst;
}

TEST(ArapHeldLengths, TheRimOfASphericalCapGetsBackItsLength) {
  const TriMesh cap = testing::spherical_cap(60, 50, 24, 64);
  const MeshTopology topology = build_mesh_topology(cap.F, cap.V.rows());
  const std::size_t rim = topology.boundary_loops.front().size();
  const std::vector<std::array<int, 2>> held = rim_edges(topology, 0, rim / 2);  // half the rim: a seam
  Eigen::MatrixXd UV = flatten(cap, topology).UV;
  const double plain_mm = length_mm(UV, held), on_cap_mm = length_mm(cap.V, held);
  ASSERT_GT(std::abs(plain_mm - on_cap_mm) / on_cap_mm, 0.01) << "plain ARAP should change the rim's length";

  const HeldLengthReport report = hold_edge_lengths(cap, topology, held, UV);
  EXPECT_LT(std::abs(length_mm(UV, held) - on_cap_mm) / on_cap_mm, 1e-3) << length_mm(UV, held) << " against " << on_cap_mm;
  EXPECT_LT(worst_edge_change(cap, UV, held), 5e-3);
  EXPECT_LT(report.energy_final, report.energy_start);
  EXPECT_GT(report.iterations, 0);
  EXPECT_EQ(measure_distortion(cap, UV, topology).flipped_triangles, 0);
  // The other half of the rim is free: it still differs from its 3D length.
  const std::vector<std::array<int, 2>> free_half = rim_edges(topology, rim / 2, rim - rim / 2);
  EXPECT_GT(std::abs(length_mm(UV, free_half) - length_mm(cap.V, free_half)) / length_mm(cap.V, free_half), 0.005);
}

TEST(ArapHeldLengths, ADevelopablePatchKeepsItsDevelopment) {
  const testing::DevelopablePatch patch = testing::cylinder_patch(40, 120, 60, 16, 10);
  const MeshTopology topology = build_mesh_topology(patch.mesh.F, patch.mesh.V.rows());
  Eigen::MatrixXd UV = flatten(patch.mesh, topology).UV;
  const std::vector<std::array<int, 2>> held = rim_edges(topology, 0, topology.boundary_loops.front().size());
  hold_edge_lengths(patch.mesh, topology, held, UV);
  EXPECT_LT(testing::max_distance_after_rigid_alignment(UV, patch.development), 1e-4);
}

TEST(ArapHeldLengths, NoHeldEdgesLeaveTheMapAsItIs) {
  const TriMesh cap = testing::spherical_cap(60, 40, 8, 24);
  const MeshTopology topology = build_mesh_topology(cap.F, cap.V.rows());
  Eigen::MatrixXd UV = flatten(cap, topology).UV;
  const Eigen::MatrixXd before = UV;
  const HeldLengthReport report = hold_edge_lengths(cap, topology, {}, UV);
  EXPECT_EQ(report.iterations, 0);
  EXPECT_EQ(UV, before);
}

}  // namespace
}  // namespace lastcut
