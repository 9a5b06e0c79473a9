// Pairwise clustering: complementary pieces merge into one piece of the instance and split again into
// exact, non-overlapping placements of the original pieces (checked with the independent Clipper checker).
#include <gtest/gtest.h>

#include <cmath>

#include "engine/nest/layout_check.hpp"
#include "engine/nest/nester.hpp"
#include "engine/nest/pair_clusters.hpp"
#include "tests/nest/nest_test_instances.hpp"

namespace lastcut {
namespace {

// Four right triangles with 10 mm legs on a 10 mm strip: two squares, a strip of 20 mm at best.
NestInstance triangle_strip() {
  NestInstance instance;
  instance.name = "triangles";
  instance.strip_height = 10;
  instance.items.push_back(test::item(3, Polygon2{{{0, 0}, {10, 0}, {0, 10}}}, 4));
  return instance;
}

double item_area(const NestItem& item) { return std::abs(signed_area(item.shape)); }

TEST(PairClusters, TwoRightTrianglesBecomeOneSquare) {
  const NestInstance instance = triangle_strip();
  const PairClusters clusters = cluster_pairs(instance, 0, 0);
  ASSERT_EQ(clusters.members.size(), 1u);
  ASSERT_EQ(clusters.instance.items.size(), 2u);
  EXPECT_EQ(clusters.instance.items[0].demand, 0);  // every triangle is in a pair
  const NestItem& pair = clusters.instance.items[1];
  EXPECT_EQ(pair.demand, 2);
  EXPECT_NEAR(item_area(pair), 100, 1e-9);
  const auto& members = clusters.members.at(pair.id);
  ASSERT_EQ(members.size(), 2u);
  EXPECT_EQ(members[0].item_id, 3);
  EXPECT_EQ(members[1].item_id, 3);
}

TEST(PairClusters, ExpandedPlacementsAreTheOriginalPiecesWithoutOverlap) {
  const NestInstance instance = triangle_strip();
  const PairClusters clusters = cluster_pairs(instance, 0, 0);
  ASSERT_EQ(clusters.members.size(), 1u);
  const int pair_id = clusters.members.begin()->first;
  // The two squares side by side, one of them turned: 20 mm of strip, full.
  Layout clustered;
  clustered.instance = instance.name;
  clustered.strip_length = 20;
  const Polygon2 square = placed_shape(clusters.instance.items[1], {pair_id, -1, 0, 0, false, 0, 0});
  double x0 = 1e9, y0 = 1e9;
  for (const Point2& p : square.points) x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y());
  clustered.placements.push_back({pair_id, -1, 0, 0, false, -x0, -y0});
  clustered.placements.push_back({pair_id, -1, 0, 180, false, 20 + x0, 10 + y0});
  const Layout layout = expand_clusters(clustered, clusters, instance);
  ASSERT_EQ(layout.placements.size(), 4u);
  for (const Placement& p : layout.placements) EXPECT_EQ(p.item, 3);
  const auto problems = check_layout(layout, instance, 0, 0);
  EXPECT_TRUE(problems.empty()) << problems.front();
  EXPECT_NEAR(layout.utilisation, 1.0, 1e-9);
}

TEST(PairClusters, NoPairsWithAKerfOrWhenPiecesMayBeMirrored) {
  EXPECT_TRUE(cluster_pairs(triangle_strip(), 0.5, 0).members.empty());
  NestInstance mirrored = triangle_strip();
  mirrored.items[0].allow_mirror = true;
  EXPECT_TRUE(cluster_pairs(mirrored, 0, 0).members.empty());
  // Unchanged when nothing pairs: the instance comes back as it was.
  EXPECT_EQ(cluster_pairs(mirrored, 0, 0).instance.items.size(), 1u);
}

TEST(PairClusters, PiecesWithManyVerticesAreLeftToTheSearch) {
  // The same triangles with their long edge cut into 200 short ones: too many vertices to pair.
  NestInstance instance = triangle_strip();
  Polygon2 fine{{{0, 0}, {10, 0}}};
  for (int k = 1; k < 200; ++k) fine.points.emplace_back(10 - k * 0.05, k * 0.05);
  fine.points.emplace_back(0, 10);
  instance.items[0].shape = fine;
  EXPECT_TRUE(cluster_pairs(instance, 0, 0).members.empty());
}

TEST(PairClusters, AnUnpairedLeftoverKeepsItsOwnDemand) {
  NestInstance instance = triangle_strip();
  instance.items[0].demand = 3;
  const PairClusters clusters = cluster_pairs(instance, 0, 0);
  ASSERT_EQ(clusters.instance.items.size(), 2u);
  EXPECT_EQ(clusters.instance.items[0].demand, 1);
  EXPECT_EQ(clusters.instance.items[1].demand, 1);
}

TEST(PairClusters, TheStripNesterPlacesTrianglesAsSquaresInTheShortestStrip) {
  const NestInstance instance = triangle_strip();
  NestOptions options;
  options.time_limit_s = 60;  // never reached
  options.iteration_limit = 20;
  const Layout layout = nest(instance, options);
  ASSERT_EQ(layout.placements.size(), 4u);
  EXPECT_TRUE(layout.unplaced.empty());
  const auto problems = check_layout(layout, instance, 0, 0);
  EXPECT_TRUE(problems.empty()) << problems.front();
  ASSERT_TRUE(layout.strip_length);
  EXPECT_LT(*layout.strip_length, 20.01);
}

}  // namespace
}  // namespace lastcut
