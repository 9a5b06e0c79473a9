// bezier_patch_weights: the patch nets as weights of the control vertices. Where the construction is
// linear (valence-4 and boundary vertices) the weighted sums are the nets of build_bezier_patches; at an
// extraordinary vertex the edge points are the regular rule's average M, whose projection onto the limit
// tangent is the true edge point.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/subdiv/bezier_patches.hpp"
#include "tests/subdiv/quad_test_meshes.hpp"

namespace lastcut {
namespace {

Eigen::Vector3d weighted(const QuadMesh& mesh, const std::vector<std::pair<int, double>>& weights, double* sum) {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  *sum = 0.0;
  for (const auto& [vertex, w] : weights) {
    point += w * mesh.V.row(vertex).transpose();
    *sum += w;
  }
  return point;
}

// Which net entries of face q are edge points next to an extraordinary corner (not on the boundary).
std::array<bool, 16> edge_points_at_extraordinary(const QuadMesh& mesh, const QuadTopology& topology, int q) {
  static constexpr int kEdgeSlots[4][2] = {{1, 4}, {2, 7}, {14, 11}, {13, 8}};  // i + 4 j along next, previous edge
  std::array<bool, 16> flags{};
  for (int k = 0; k < 4; ++k) {
    const int v = mesh.Q(q, k);
    if (topology.valence(v) == 4 || topology.on_boundary[static_cast<size_t>(v)] != 0) continue;
    flags[static_cast<size_t>(kEdgeSlots[k][0])] = flags[static_cast<size_t>(kEdgeSlots[k][1])] = true;
  }
  return flags;
}

TEST(BezierPatchWeights, ReproduceTheNetsOfAnOpenGridExactly) {
  const QuadMesh grid = test::height_grid(6, 5, 3);
  const QuadTopology topology = build_quad_topology(grid);
  const std::vector<BezierPatch> patches = build_bezier_patches(grid, topology);
  const std::vector<PatchWeights> weights = bezier_patch_weights(grid, topology);
  ASSERT_EQ(weights.size(), patches.size());
  for (size_t q = 0; q < patches.size(); ++q) {
    for (size_t b = 0; b < 16; ++b) {
      double sum = 0.0;
      EXPECT_LT((weighted(grid, weights[q].b[b], &sum) - patches[q].b[b]).norm(), 1e-12) << "face " << q << " point " << b;
      EXPECT_NEAR(sum, 1.0, 1e-14);  // an affine combination
    }
  }
}

TEST(BezierPatchWeights, AtExtraordinaryVerticesTheEdgePointsProjectOntoTheTrueOnes) {
  for (const QuadMesh& mesh : {test::cube_sphere(4, 20.0), test::pentagon_prism(20.0)}) {
    const QuadTopology topology = build_quad_topology(mesh);
    const std::vector<BezierPatch> patches = build_bezier_patches(mesh, topology);
    const std::vector<PatchWeights> weights = bezier_patch_weights(mesh, topology);
    int projected = 0;
    for (int q = 0; q < mesh.quad_count(); ++q) {
      const std::array<bool, 16> at_extraordinary = edge_points_at_extraordinary(mesh, topology, q);
      const BezierPatch& patch = patches[static_cast<size_t>(q)];
      for (size_t b = 0; b < 16; ++b) {
        double sum = 0.0;
        const Eigen::Vector3d point = weighted(mesh, weights[static_cast<size_t>(q)].b[b], &sum);
        EXPECT_NEAR(sum, 1.0, 1e-14);
        if (!at_extraordinary[b]) {
          EXPECT_LT((point - patch.b[b]).norm(), 1e-12) << "face " << q << " point " << b;
          continue;
        }
        // The corner next to this edge point (its row or column end): E = P + d (d . (M - P)), d = (E - P) / |E - P|.
        const int i = static_cast<int>(b % 4), j = static_cast<int>(b / 4);
        const Eigen::Vector3d& corner = patch.at(i < 2 ? 0 : 3, j < 2 ? 0 : 3);
        const Eigen::Vector3d true_edge = patch.b[b] - corner, linear_edge = point - corner;
        EXPECT_NEAR(linear_edge.dot(true_edge), true_edge.squaredNorm(), 1e-9 * true_edge.squaredNorm());
        ++projected;
      }
    }
    EXPECT_GT(projected, 0);
  }
}

}  // namespace
}  // namespace lastcut
