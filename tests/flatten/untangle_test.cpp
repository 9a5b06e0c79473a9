// Untangling folded flattenings: single vertices pushed through their star, a folded block of vertices and
// a fold at the outline are untangled by moving only a few rings; everything farther away stays put.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <queue>

#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/distortion.hpp"
#include "engine/flatten/star_untangle.hpp"
#include "engine/flatten/untangle.hpp"
#include "tests/flatten/flatten_fixtures.hpp"

namespace lastcut {
namespace {

struct Folded {
  TriMesh mesh;
  MeshTopology topology;
  TriangleFrames frames;
  Eigen::MatrixXd flat;  // flip-free development
};

Folded developed_cylinder() {
  testing::DevelopablePatch patch = testing::cylinder_patch(40.0, 120.0, 60.0, 16, 12);
  Folded f{patch.mesh, check_disk(patch.mesh), compute_triangle_frames(patch.mesh), patch.development};
  EXPECT_EQ(count_flipped_triangles(f.mesh.F, f.flat), 0);
  return f;
}

// Ring distance of every vertex from the given ones.
std::vector<int> rings_from(const MeshTopology& topology, const std::vector<int>& seeds, int vertex_count) {
  std::vector<int> distance(vertex_count, -1);
  std::queue<int> queue;
  for (int v : seeds) {
    distance[v] = 0;
    queue.push(v);
  }
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop();
    for (int k = topology.neighbor_offsets[v]; k < topology.neighbor_offsets[v + 1]; ++k) {
      const int w = topology.neighbors[k];
      if (distance[w] < 0) {
        distance[w] = distance[v] + 1;
        queue.push(w);
      }
    }
  }
  return distance;
}

int interior_vertex_near(const Folded& f, double u, double v) {
  std::vector<char> on_boundary(f.mesh.vertex_count(), 0);
  for (int b : f.topology.boundary_loops[0]) on_boundary[b] = 1;
  int best = -1;
  for (int i = 0; i < f.mesh.vertex_count(); ++i) {
    if (on_boundary[i]) continue;
    if (best < 0 || (f.flat.row(i) - Eigen::RowVector2d(u, v)).norm() < (f.flat.row(best) - Eigen::RowVector2d(u, v)).norm()) {
      best = i;
    }
  }
  return best;
}

void expect_untangled_locally(const Folded& f, const Eigen::MatrixXd& folded, const Eigen::MatrixXd& repaired,
                              const std::vector<int>& moved_on_purpose, int max_rings_moved) {
  EXPECT_EQ(count_flipped_triangles(f.mesh.F, repaired), 0);
  const std::vector<int> distance = rings_from(f.topology, moved_on_purpose, f.mesh.vertex_count());
  for (int v = 0; v < f.mesh.vertex_count(); ++v) {
    if (distance[v] > max_rings_moved) {
      EXPECT_EQ(repaired.row(v), folded.row(v)) << "vertex " << v << " is " << distance[v] << " rings away";
    }
  }
}

TEST(StarUntangle, VertexPushedThroughItsStarComesBack) {
  const Folded f = developed_cylinder();
  const Eigen::RowVector2d centre = f.flat.colwise().mean();
  const int v = interior_vertex_near(f, centre.x(), centre.y());
  Eigen::MatrixXd folded = f.flat;
  folded.row(v) += Eigen::RowVector2d(9.0, 7.0);  // several cells away: its star folds over its neighbours
  ASSERT_GT(count_flipped_triangles(f.mesh.F, folded), 0);
  Eigen::MatrixXd repaired = folded;
  const StarUntangleReport report = star_untangle(f.frames, f.topology, repaired);
  EXPECT_GT(report.flipped_before, 0);
  EXPECT_EQ(report.flipped_after, 0);
  expect_untangled_locally(f, folded, repaired, {v}, 2);
}

TEST(StarUntangle, FoldedBlockAndFoldedOutlineAreUntangled) {
  const Folded f = developed_cylinder();
  Eigen::MatrixXd folded = f.flat;
  // A block of neighbouring vertices shifted together across a row of cells, and an outline vertex pushed
  // inside the mold across its inner neighbours.
  const Eigen::RowVector2d centre = f.flat.colwise().mean();
  std::vector<int> moved;
  for (double du : {-3.0, 0.0, 3.0}) {
    const int v = interior_vertex_near(f, centre.x() + du, centre.y());
    folded.row(v) += Eigen::RowVector2d(0.0, 8.0);
    moved.push_back(v);
  }
  const int outline = f.topology.boundary_loops[0][f.topology.boundary_loops[0].size() / 3];
  folded.row(outline) = 0.5 * (f.flat.row(outline) + centre) ;
  moved.push_back(outline);
  const int flips = count_flipped_triangles(f.mesh.F, folded);
  ASSERT_GT(flips, 3);
  Eigen::MatrixXd repaired = folded;
  const UntangleReport report = untangle_flips(f.frames, f.topology, repaired);
  EXPECT_EQ(report.flipped_before, flips);
  EXPECT_EQ(report.flipped_after, 0);
  expect_untangled_locally(f, folded, repaired, moved, 9);
}

TEST(StarUntangle, SwirledDiscIsUntangled) {
  // Every vertex within 12 mm of the middle turned about it by up to 340 degrees (most at the centre):
  // overlapping triangles over many neighbouring stars, untangled together.
  const Folded f = developed_cylinder();
  const Eigen::RowVector2d centre = f.flat.colwise().mean();
  Eigen::MatrixXd folded = f.flat;
  std::vector<int> moved;
  for (int v = 0; v < f.mesh.vertex_count(); ++v) {
    const Eigen::RowVector2d offset = f.flat.row(v) - centre;
    const double r = offset.norm();
    if (r >= 12.0) continue;
    const double angle = 6.0 * (1.0 - r / 12.0);
    folded.row(v) = centre + Eigen::RowVector2d(std::cos(angle) * offset.x() - std::sin(angle) * offset.y(),
                                                std::sin(angle) * offset.x() + std::cos(angle) * offset.y());
    moved.push_back(v);
  }
  const int flips = count_flipped_triangles(f.mesh.F, folded);
  ASSERT_GT(flips, 10);
  Eigen::MatrixXd repaired = folded;
  const UntangleReport report = untangle_flips(f.frames, f.topology, repaired);
  std::printf("%d flipped, repaired within %d rings, %d vertices moved\n", flips, report.rings, report.moved_vertices);
  EXPECT_EQ(report.flipped_after, 0);
  expect_untangled_locally(f, folded, repaired, moved, 16);
}

TEST(StarUntangle, FlipFreeMapIsLeftAlone) {
  const Folded f = developed_cylinder();
  Eigen::MatrixXd same = f.flat;
  const StarUntangleReport report = star_untangle(f.frames, f.topology, same);
  EXPECT_EQ(report.flipped_before, 0);
  EXPECT_EQ(report.sweeps, 0);
  EXPECT_EQ(same, f.flat);
}

}  // namespace
}  // namespace lastcut
