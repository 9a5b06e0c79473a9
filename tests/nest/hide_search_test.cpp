// The hide search (the default hide method) on hand-made hides with a hole, a low-grade zone, a
// backbone and a pair group: every layout passes the independent checker, the constraints hold when
// measured here directly, the search is deterministic for seed + rounds, never uses more hides than
// the greedy, keeps the most valuable pieces when not all fit, and drops a pair group whole.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <thread>

#include "engine/nest/layout_check.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/nest/nester.hpp"
#include "hide_test_instances.hpp"

namespace lastcut {
namespace {

NestOptions rounds(long n, HideMethod method = HideMethod::Search) {
  NestOptions options;
  options.time_limit_s = 60;  // never reached: the round budget ends the search
  options.iteration_limit = n;
  options.hide_method = method;
  return options;
}

std::string all(const std::vector<std::string>& problems) {
  std::string text;
  for (const auto& p : problems) text += p + "; ";
  return text;
}

// Axis deviation (deg, 0..90) between two undirected lines.
double line_deviation_deg(double a_deg, double b_deg) {
  const double d = std::fmod(std::abs(a_deg - b_deg), 180.0);
  return std::min(d, 180.0 - d);
}

TEST(NestHideSearch, AllConstraintsHoldOnOneHide) {
  const NestInstance instance = test::constraint_instance(2);
  const Layout layout = nest(instance, rounds(10));
  EXPECT_TRUE(check_layout(layout, instance).empty()) << all(check_layout(layout, instance));
  EXPECT_EQ(layout.placements.size(), 7u);
  EXPECT_TRUE(layout.unplaced.empty());
  EXPECT_EQ(used_bin_count(layout), 1);  // 25,950 mm^2 of pieces on a hide of ~230,000 mm^2
  int pair_bin = -1;
  for (const Placement& p : layout.placements) {
    if (p.item == 0) {
      EXPECT_LE(line_deviation_deg(p.rotation_deg, 30), 5 + 1e-9);  // grain 0 along the 30 deg backbone
    }
    if (p.item == 1 || p.item == 2) {
      if (pair_bin < 0) pair_bin = p.bin;
      EXPECT_EQ(p.bin, pair_bin);
    }
  }
}

TEST(NestHideSearch, SameSeedAndRoundsGiveTheSameLayout) {
  NestInstance instance = test::constraint_instance(3);
  instance.items[3].demand = 40;  // more than one hide
  const Layout a = nest(instance, rounds(4));
  const Layout b = nest(instance, rounds(4));
  ASSERT_EQ(a.placements.size(), b.placements.size());
  for (size_t k = 0; k < a.placements.size(); ++k) {
    EXPECT_EQ(a.placements[k].bin, b.placements[k].bin);
    EXPECT_EQ(a.placements[k].x, b.placements[k].x);
    EXPECT_EQ(a.placements[k].y, b.placements[k].y);
    EXPECT_EQ(a.placements[k].rotation_deg, b.placements[k].rotation_deg);
  }
}

TEST(NestHideSearch, NeverMoreHidesThanTheGreedyAndAtLeastTheAreaBound) {
  NestInstance instance = test::constraint_instance(4);
  instance.items[3].demand = 70;  // 168,000 mm^2 of fillers
  const Layout search = nest(instance, rounds(4));
  const Layout greedy = nest(instance, rounds(4, HideMethod::Greedy));
  EXPECT_TRUE(check_layout(search, instance).empty()) << all(check_layout(search, instance));
  EXPECT_TRUE(check_layout(greedy, instance).empty());
  EXPECT_EQ(search.placements.size(), greedy.placements.size());
  EXPECT_LE(used_bin_count(search), used_bin_count(greedy));
  // Independent lower bound: placed area over one hide's area (outer minus hole).
  const double hide_area = std::abs(signed_area(instance.bins[0].outer)) - 50.0 * 50.0;
  const double placed = placed_item_area(search, instance);
  EXPECT_GE(used_bin_count(search), static_cast<int>(std::ceil(placed / hide_area)));
}

TEST(NestHideSearch, KeepsTheHighestPriorityWhenNotEverythingFits) {
  NestInstance instance = test::constraint_instance(1);
  instance.items[3].demand = 120;  // far more than one hide holds
  NestItem urgent = test::item(4, test::rectangle(70, 45), 4);
  urgent.priority = 5;
  instance.items.push_back(urgent);
  const Layout layout = nest(instance, rounds(6));
  EXPECT_TRUE(check_layout(layout, instance).empty()) << all(check_layout(layout, instance));
  int urgent_placed = 0;
  for (const Placement& p : layout.placements) urgent_placed += p.item == 4 ? 1 : 0;
  EXPECT_EQ(urgent_placed, 4);
  EXPECT_FALSE(layout.unplaced.empty());
}

// One 100 mm hide; a 54 mm square (the most valuable piece, placed first by value) leaves no room for
// any of four 46 mm squares, which fill the hide 2 x 2 when one of them comes first (gap 2 mm). Once the
// left-overs have failed, the search must try other orders (a perturbed greedy, as the iterated greedy
// does) instead of ending with its budget unused on the 29 % layout.
TEST(NestHideSearch, OnOneHideTriesOtherOrdersWhenTheMostValuablePieceBlocksTheRest) {
  NestInstance instance;
  instance.name = "blocking-square";
  Bin hide;
  hide.id = 1;
  hide.name = "square";
  hide.outer = test::rectangle(100, 100);
  instance.bins.push_back(hide);
  instance.items.push_back(test::item(0, test::rectangle(54, 54), 1, {0}));
  instance.items.push_back(test::item(1, test::rectangle(46, 46), 4, {0}));
  instance.gap_mm = 2;
  instance.margin_mm = 0;
  const Layout layout = nest(instance, rounds(600));
  EXPECT_TRUE(check_layout(layout, instance).empty()) << all(check_layout(layout, instance));
  int small_placed = 0;
  for (const Placement& p : layout.placements) small_placed += p.item == 1 ? 1 : 0;
  EXPECT_EQ(small_placed, 4) << layout.placements.size() << " placed";
}

TEST(NestHideSearch, APairThatCannotBeNearIsLeftOutWhole) {
  NestInstance instance = test::constraint_instance(1);
  instance.pair_distance_mm = 1;  // no two pieces can have centroids 1 mm apart
  const Layout layout = nest(instance, rounds(3));
  EXPECT_TRUE(check_layout(layout, instance).empty()) << all(check_layout(layout, instance));
  for (const Placement& p : layout.placements) EXPECT_TRUE(p.item != 1 && p.item != 2);
  int listed = 0;
  for (const Unplaced& u : layout.unplaced)
    if (u.item == 1 || u.item == 2) {
      listed += u.count;
      EXPECT_NE(u.reason.find("pair group order-1"), std::string::npos) << u.reason;
    }
  EXPECT_EQ(listed, 2);
}

TEST(NestHideSearch, MovesThePiecesOntoASmallerHideThatHoldsThem) {
  // The greedy opens the larger hide first (the same price per hide, so cheaper per mm^2); four
  // 100 x 100 squares (40,000 mm^2) also fit the 400 x 300 hide (120,000 mm^2 less the margin strip).
  NestInstance instance;
  instance.name = "two hides";
  Bin large;
  large.id = 1;
  large.outer = test::rectangle(1000, 1000);
  Bin small = large;
  small.id = 2;
  small.outer = test::rectangle(400, 300);
  instance.bins = {large, small};
  instance.items.push_back(test::item(0, test::rectangle(100, 100), 4));
  instance.gap_mm = 2;
  instance.margin_mm = 5;
  const Layout greedy = nest(instance, rounds(10, HideMethod::Greedy));
  const Layout search = nest(instance, rounds(10));
  EXPECT_TRUE(check_layout(search, instance).empty()) << all(check_layout(search, instance));
  ASSERT_EQ(search.placements.size(), 4u);
  ASSERT_EQ(greedy.placements.size(), 4u);
  for (const Placement& p : greedy.placements) EXPECT_EQ(p.bin, 1);
  for (const Placement& p : search.placements) EXPECT_EQ(p.bin, 2);
  // Utilisation of the used hide: the pieces' area over the small hide's area.
  EXPECT_NEAR(search.utilisation, 4 * 100.0 * 100.0 / (400.0 * 300.0), 1e-9);
  // A dearer small hide is not taken.
  instance.bins[1].cost = 2;
  for (const Placement& p : nest(instance, rounds(10)).placements) EXPECT_EQ(p.bin, 1);
}

// Baldacci Test6 with seed 6: the greedy start fills all 15 hides and leaves one piece over. The left-over
// unit tried the used hides (two at a time, most free area first) and never the hides the moves had
// emptied, which came last behind that limit: 42 of 43 pieces to the end of a 60 s run. The unused
// hides now get their own tries: every piece is placed within 4 rounds (0.8 s here).
TEST(NestHideSearch, APieceLeftOverByTheStartReachesAHideTheMovesEmptied) {
  const NestInstance instance = read_nest_instance(LASTCUT_SHARED_DATA_DIR "/nesting/leather/baldacci6.json");
  NestOptions options = rounds(4);
  options.seed = 6;
  const Layout layout = nest(instance, options);
  EXPECT_TRUE(check_layout(layout, instance).empty()) << all(check_layout(layout, instance));
  EXPECT_EQ(layout.placements.size(), 43u);
  EXPECT_TRUE(layout.unplaced.empty());
}

TEST(NestHideSearch, GreedyMethodHonoursTheSameConstraints) {
  const NestInstance instance = test::constraint_instance(2);
  const Layout layout = nest(instance, rounds(3, HideMethod::Greedy));
  EXPECT_TRUE(check_layout(layout, instance).empty()) << all(check_layout(layout, instance));
  EXPECT_EQ(layout.placements.size(), 7u);
}

}  // namespace
}  // namespace lastcut
