// The outer hull chain of an open polyline (engine/mold/outer_hull_chain.hpp): dents on the outward
// side (right of travel) bridged, bulges kept, the ends kept, and the polyline as it is when an end is
// not extreme along the chord.
#include <gtest/gtest.h>

#include "engine/mold/outer_hull_chain.hpp"

namespace lastcut {
namespace {

TEST(OuterHullChain, BridgesDentsAndKeepsBulges) {
  // Left to right, outward is down (-y): a top edge kinked inward (up) in its middle becomes its chord.
  const std::vector<Point2> kinked = {{0, 0}, {10, 2}, {20, 5}, {30, 2}, {40, 0}};
  EXPECT_EQ(outer_hull_chain(kinked), (std::vector<Point2>{{0, 0}, {40, 0}}));
  // Bulging outward (down) it is its own hull chain.
  const std::vector<Point2> bulging = {{0, 0}, {10, -3}, {20, -4}, {30, -3}, {40, 0}};
  EXPECT_EQ(outer_hull_chain(bulging), bulging);
  // A dent between two bulges is bridged, the bulges kept.
  const std::vector<Point2> dented = {{0, 0}, {10, -4}, {20, 3}, {30, -4}, {40, 0}};
  EXPECT_EQ(outer_hull_chain(dented), (std::vector<Point2>{{0, 0}, {10, -4}, {30, -4}, {40, 0}}));
}

TEST(OuterHullChain, LeavesThePolylineWhenAnEndIsNotExtreme) {
  // It runs back past its start along the chord: no chain from end to end, the points as they are.
  const std::vector<Point2> hooked = {{0, 0}, {-5, 3}, {20, 5}, {40, 0}};
  EXPECT_EQ(outer_hull_chain(hooked), hooked);
  const std::vector<Point2> two = {{0, 0}, {40, 0}};
  EXPECT_EQ(outer_hull_chain(two), two);
}

}  // namespace
}  // namespace lastcut
