// MeshTopology on small hand-made meshes whose connectivity is known: a disk, an annulus, a closed
// tetrahedron, a crowded (non-manifold) edge, flipped neighbours, two pieces and ignored faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/core/mesh_topology.hpp"

namespace lastcut {
namespace {

Eigen::MatrixXi faces(const std::vector<Eigen::RowVector3i>& rows) {
  Eigen::MatrixXi F(static_cast<Eigen::Index>(rows.size()), 3);
  for (std::size_t i = 0; i < rows.size(); ++i) F.row(static_cast<Eigen::Index>(i)) = rows[i];
  return F;
}

// Fan of six counter-clockwise triangles around vertex 0: a disk bounded by 1..6.
Eigen::MatrixXi hexagon_fan() {
  std::vector<Eigen::RowVector3i> rows;
  for (int i = 0; i < 6; ++i) rows.emplace_back(0, 1 + i, 1 + (i + 1) % 6);
  return faces(rows);
}

// Ring of 8 triangles between an outer square 0..3 and an inner square 4..7, counter-clockwise.
Eigen::MatrixXi square_annulus() {
  std::vector<Eigen::RowVector3i> rows;
  for (int i = 0; i < 4; ++i) {
    const int o = i, o1 = (i + 1) % 4, n = 4 + i, n1 = 4 + (i + 1) % 4;
    rows.emplace_back(o, o1, n1);
    rows.emplace_back(o, n1, n);
  }
  return faces(rows);
}

std::vector<int> neighbours_of(const MeshTopology& t, int v) {
  return {t.neighbors.begin() + t.neighbor_offsets[static_cast<std::size_t>(v)],
          t.neighbors.begin() + t.neighbor_offsets[static_cast<std::size_t>(v) + 1]};
}

TEST(MeshTopology, DiskHasOneLoopInFaceOrder) {
  const MeshTopology t = build_mesh_topology(hexagon_fan(), 7);
  ASSERT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_EQ(t.boundary_loops[0], (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(t.boundary_half_edges, 6);
  EXPECT_EQ(t.edge_count(), 12);  // Euler: 7 - 12 + 6 = 1
  EXPECT_EQ(t.first_pinch_vertex, -1);
  EXPECT_EQ(t.open_boundary_chains, 0);
  EXPECT_EQ(neighbours_of(t, 0), (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(neighbours_of(t, 1), (std::vector<int>{0, 2, 6}));  // 6 only reaches 1 by a boundary half-edge
}

TEST(MeshTopology, TwinAndFaceAcross) {
  const MeshTopology t = build_mesh_topology(hexagon_fan(), 7);
  // Face 0 is 0 -> 1 -> 2; its half-edge 1 -> 0 is h = 2 ... the spoke 0 -> 2 (h = 3 * 1) of face 1
  // runs against 2 -> 0 (h = 3 * 0 + 2) of face 0.
  EXPECT_EQ(t.find_half_edge(0, 2), 3);
  EXPECT_EQ(t.find_half_edge(2, 0), 2);
  EXPECT_EQ(t.find_half_edge(1, 3), -1);
  EXPECT_EQ(t.twin(3), 2);
  EXPECT_EQ(t.twin(2), 3);
  EXPECT_EQ(t.face_across(3), 0);
  EXPECT_EQ(t.face_across(1), kBoundaryEdge);  // 1 -> 2 is on the rim
  EXPECT_EQ(t.twin(1), -1);
  EXPECT_FALSE(t.same_direction[3]);
}

TEST(MeshTopology, AnnulusHasOuterAndInnerLoopsRunningOpposite) {
  const MeshTopology t = build_mesh_topology(square_annulus(), 8);
  ASSERT_EQ(t.boundary_loops.size(), 2u);
  EXPECT_EQ(t.boundary_loops[0], (std::vector<int>{0, 1, 2, 3}));  // outer: counter-clockwise
  EXPECT_EQ(t.boundary_loops[1], (std::vector<int>{4, 7, 6, 5}));  // hole: clockwise
  EXPECT_EQ(8 - t.edge_count() + 8, 0);                            // Euler characteristic of an annulus
}

TEST(MeshTopology, ClosedTetrahedronHasNoBoundary) {
  const MeshTopology t = build_mesh_topology(faces({{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}), 4);
  EXPECT_TRUE(t.boundary_loops.empty());
  EXPECT_EQ(t.boundary_half_edges, 0);
  for (int h = 0; h < 12; ++h) {
    EXPECT_GE(t.twin(h), 0) << h;
    EXPECT_EQ(t.twin(t.twin(h)), h) << h;
  }
  int count = 0;
  face_components(t, {}, count);
  EXPECT_EQ(count, 1);
}

TEST(MeshTopology, CrowdedEdgeIsMarkedAndSplitsNothing) {
  // Three triangles on the edge 0-1 (a fin): every half-edge on it is crowded.
  const MeshTopology t = build_mesh_topology(faces({{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}), 5);
  EXPECT_EQ(t.across[0], kCrowdedEdge);
  EXPECT_EQ(t.across[3], kCrowdedEdge);
  EXPECT_EQ(t.across[6], kCrowdedEdge);
  EXPECT_EQ(t.face_across(0), kCrowdedEdge);
  EXPECT_EQ(t.twin(0), -1);
  EXPECT_EQ(t.across[1], kBoundaryEdge);
  int count = 0;
  const std::vector<int> component = face_components(t, {}, count);
  EXPECT_EQ(count, 3);  // no face is joined across a crowded edge
  EXPECT_EQ(neighbours_of(t, 0), (std::vector<int>{1, 2, 3, 4}));
}

TEST(MeshTopology, FlippedNeighbourRunsTheEdgeTheSameWay) {
  const MeshTopology t = build_mesh_topology(faces({{0, 1, 2}, {0, 1, 3}}), 4);
  EXPECT_EQ(t.across[0], 3);
  EXPECT_EQ(t.across[3], 0);
  EXPECT_TRUE(t.same_direction[0]);
  EXPECT_EQ(t.face_across(0), 1);
  EXPECT_EQ(t.twin(0), -1);  // no half-edge runs 1 -> 0
  // The rim then does not chain into a loop: 1 -> 2 -> 0 ends where 0 -> 3 -> 1 starts.
  EXPECT_TRUE(t.boundary_loops.empty());
  EXPECT_GT(t.open_boundary_chains, 0);
}

TEST(MeshTopology, BowTieIsAPinch) {
  // Two triangles touching at vertex 0 only.
  const MeshTopology t = build_mesh_topology(faces({{0, 1, 2}, {0, 3, 4}}), 5);
  EXPECT_EQ(t.first_pinch_vertex, 0);
  EXPECT_EQ(t.boundary_loops.size(), 2u);
  int count = 0;
  EXPECT_EQ(face_components(t, {}, count), (std::vector<int>{0, 1}));
  EXPECT_EQ(count, 2);
}

TEST(MeshTopology, ComponentsOfASubsetAndTheirAreas) {
  // Two hexagon fans side by side (vertices 0..6 and 7..13).
  Eigen::MatrixXi F(12, 3);
  F.topRows(6) = hexagon_fan();
  F.bottomRows(6) = hexagon_fan().array() + 7;
  const MeshTopology t = build_mesh_topology(F, 14);
  int count = 0;
  std::vector<char> in_set(12, 1);
  in_set[0] = in_set[3] = 0;  // splits the first fan into faces 1-2 and 4-5
  const std::vector<int> component = face_components(t, in_set, count);
  EXPECT_EQ(count, 3);
  EXPECT_EQ(component, (std::vector<int>{-1, 0, 0, -1, 1, 1, 2, 2, 2, 2, 2, 2}));
  const std::vector<double> areas = component_areas(component, count, Eigen::VectorXd::Constant(12, 0.5));
  EXPECT_EQ(areas, (std::vector<double>{1.0, 1.0, 3.0}));
}

TEST(MeshTopology, IgnoredFacesAreLeftOut) {
  std::vector<char> ignored(6, 0);
  ignored[0] = 1;  // the fan loses face 0 -> 1 -> 2: the rim now runs 0 -> 2 ... 6 -> 1 -> 0
  const MeshTopology t = build_mesh_topology(hexagon_fan(), 7, ignored);
  EXPECT_EQ(t.across[0], kBoundaryEdge);
  EXPECT_EQ(t.face_across(3), kBoundaryEdge);  // 0 -> 2 of face 1 lost its neighbour
  ASSERT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_EQ(t.boundary_loops[0], (std::vector<int>{0, 2, 3, 4, 5, 6, 1}));
  EXPECT_EQ(neighbours_of(t, 1), (std::vector<int>{0, 6}));
}

TEST(MeshTopology, RefusesAnIndexOutOfRange) {
  try {
    build_mesh_topology(faces({{0, 1, 5}}), 3);
    ADD_FAILURE() << "accepted a face with vertex 5 of 3";
  } catch (const EngineError& error) {
    EXPECT_NE(std::string(error.what()).find("refers to vertex 5"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace lastcut
