// for_each_near_edge_pair against the brute force over all pairs (the oracle): on random rings with
// long edges, repeated points and collinear runs, each pair whose grown boxes meet is visited exactly
// once and no other; the grid stays small where one edge spans a dense drawing; a stop and a NaN end the
// scan as documented.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "engine/core/near_edge_pairs.hpp"

namespace lastcut {
namespace {

using Pairs = std::set<std::pair<int, int>>;

bool boxes_meet(const std::vector<Point2>& p, int i, int j, double reach) {
  const int n = static_cast<int>(p.size());
  const Point2 &a = p[i], &b = p[(i + 1) % n], &c = p[j], &d = p[(j + 1) % n];
  return std::min(a.x(), b.x()) - reach <= std::max(c.x(), d.x()) + reach &&
         std::min(c.x(), d.x()) - reach <= std::max(a.x(), b.x()) + reach &&
         std::min(a.y(), b.y()) - reach <= std::max(c.y(), d.y()) + reach &&
         std::min(c.y(), d.y()) - reach <= std::max(a.y(), b.y()) + reach;
}

Pairs brute_force(const std::vector<Point2>& p, double reach) {
  const int n = static_cast<int>(p.size());
  Pairs pairs;
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n; ++j)
      if (!(i == 0 && j == n - 1) && boxes_meet(p, i, j, reach)) pairs.emplace(i, j);
  return pairs;
}

// Every visited pair, ordered; fails the test when a pair comes twice.
Pairs scanned(const std::vector<Point2>& p, double reach) {
  Pairs pairs;
  const EdgePairScan scan = for_each_near_edge_pair(
      static_cast<int>(p.size()), [&](int k) { return p[static_cast<size_t>(k)]; }, reach, [&](int i, int j) {
        EXPECT_TRUE(pairs.emplace(std::min(i, j), std::max(i, j)).second) << "pair " << i << ", " << j << " twice";
        return true;
      });
  EXPECT_EQ(scan, EdgePairScan::Completed);
  return pairs;
}

std::vector<Point2> random_ring(std::mt19937& random, int n) {
  std::uniform_real_distribution<double> coordinate(0.0, 100.0);
  std::uniform_int_distribution<int> kind(0, 9);
  std::vector<Point2> ring;
  for (int k = 0; k < n; ++k) {
    const int what = kind(random);
    if (what == 0 && !ring.empty()) {
      ring.push_back(ring.back());  // a repeated point
    } else if (what == 1 && ring.size() >= 2) {
      ring.push_back(2.0 * ring.back() - ring[ring.size() - 2]);  // collinear with the last edge
    } else if (what <= 3 && !ring.empty()) {
      ring.push_back(ring.back() + Point2(coordinate(random), coordinate(random)) * 0.01);  // a short edge
    } else {
      ring.emplace_back(coordinate(random), coordinate(random));  // a long one
    }
  }
  return ring;
}

TEST(NearEdgePairs, VisitsExactlyThePairsWhoseGrownBoxesMeet) {
  std::mt19937 random(20261126);
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 4 + trial * 5;
    const std::vector<Point2> ring = random_ring(random, n);
    for (double reach : {0.0, 0.05, 3.0}) EXPECT_EQ(scanned(ring, reach), brute_force(ring, reach)) << n << " " << reach;
  }
}

TEST(NearEdgePairs, AFineOutlineWithOneEdgeAcrossTheDrawingKeepsTheGridSmall) {
  // 3000 points 0.015 mm apart along x and one edge back across a 2 m drawing: the grid this replaced
  // entered that edge in every cell of its box (millions for 20,000 points).
  std::vector<Point2> ring;
  for (int k = 0; k < 3000; ++k) ring.emplace_back(0.015 * k, (k % 2) * 0.01);
  ring.emplace_back(2000.0, 1500.0);
  EXPECT_EQ(scanned(ring, 0.0), brute_force(ring, 0.0));
}

TEST(NearEdgePairs, AStopAndANonFinitePointEndTheScan) {
  std::vector<Point2> bow_tie = {{0, 0}, {10, 10}, {10, 0}, {0, 10}};
  int visits = 0;
  EXPECT_EQ(for_each_near_edge_pair(4, [&](int k) { return bow_tie[static_cast<size_t>(k)]; }, 0.0,
                                    [&](int, int) { return ++visits < 1; }),
            EdgePairScan::Stopped);
  EXPECT_EQ(visits, 1);
  bow_tie[2].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(for_each_near_edge_pair(4, [&](int k) { return bow_tie[static_cast<size_t>(k)]; }, 0.0,
                                    [&](int, int) { return true; }),
            EdgePairScan::NotFinite);
  // A triangle has no pair of edges that share no vertex.
  EXPECT_EQ(for_each_near_edge_pair(3, [&](int k) { return Point2(k, k * k); }, 1.0, [&](int, int) {
              ADD_FAILURE();
              return true;
            }),
            EdgePairScan::Completed);
}

}  // namespace
}  // namespace lastcut
