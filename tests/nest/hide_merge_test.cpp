// The merge (engine/nest/hide_merge) on square hides whose answers follow from arithmetic: two small
// used hides, each with one square, give way to a larger unused hide that takes both squares; which
// pairs qualify follows from the fill of the hides left, by area. Results are checked by the
// independent layout checker.
#include <gtest/gtest.h>

#include "engine/nest/hide_merge.hpp"
#include "engine/nest/layout_check.hpp"
#include "hide_assignment.hpp"
#include "nest_test_instances.hpp"

namespace lastcut {
namespace {

using namespace nest_detail;
using test::HideAssignment;
using test::pieces_on;
using test::put;

constexpr double kBigMm = 230, kSmallMm = 130, kGapMm = 2, kMarginMm = 5;
// The room a piece's inflated outline may use: the hide less (margin - gap/2) on each side.
constexpr double kRoomMm = kBigMm - 2 * (kMarginMm - kGapMm / 2);

// Bins 0 and 1: 230 x 230; bins 2 and 3: 230 x 130. Six 100 mm squares.
NestInstance merge_instance() {
  NestInstance instance;
  instance.name = "merge";
  for (int h = 0; h < 4; ++h) {
    Bin bin;
    bin.id = h + 1;
    bin.outer = test::rectangle(kBigMm, h < 2 ? kBigMm : kSmallMm);
    instance.bins.push_back(bin);
  }
  instance.items.push_back(test::item(0, test::rectangle(100, 100), 6));
  instance.gap_mm = kGapMm;
  instance.margin_mm = kMarginMm;
  return instance;
}

TEST(HideMerge, TwoSmallHidesGiveWayToALargerUnusedOne) {
  // A big hide holds four squares only as a 2 x 2 block (2 x 102 <= 222 < 3 x 102), a small one one
  // square (102 <= 130 - 8 < 2 x 102 in height).
  static_assert(2 * (100 + kGapMm) <= kRoomMm && 3 * (100 + kGapMm) > kRoomMm);
  static_assert(100 + kGapMm <= kSmallMm - 2 * (kMarginMm - kGapMm / 2));
  const NestInstance instance = merge_instance();
  NestOptions options;
  const HidePieces pieces = prepare_hide_pieces(instance, options);
  ASSERT_EQ(pieces.item_of.size(), 6u);
  // Opening order: the big hides first.
  const int full = 0, spare = 1, small_a = 2, small_b = 3;
  ASSERT_EQ(pieces.slots[full].bin_index, 0);
  ASSERT_EQ(pieces.slots[spare].bin_index, 1);
  ASSERT_EQ(pieces.slots[small_a].bin_index, 2);
  ASSERT_EQ(pieces.slots[small_b].bin_index, 3);
  HideAssignment a{std::vector<int>(6, -1), std::vector<PieceState>(6)};
  for (int k = 0; k < 4; ++k) ASSERT_TRUE(put(pieces, a, k, full, k % 2 ? kBigMm : 0, k / 2 ? kBigMm : 0));
  ASSERT_TRUE(put(pieces, a, 4, small_a, kBigMm / 2, kSmallMm / 2));
  ASSERT_TRUE(put(pieces, a, 5, small_b, kBigMm / 2, kSmallMm / 2));
  ASSERT_TRUE(check_layout(hide_layout(instance, pieces, a.slot_of, a.state, {}), instance).empty());

  // The fill of the hides left, by area: six squares over two big hides (the small pair merged) or
  // over a big and a small one (a small hide merged with the full big one). Usable area: the room
  // inside the margin, about 222 x 222 and 222 x 122 mm.
  const double squares = 6 * 100.0 * 100, big = pieces.slots[full].container->usable_area_mm2(),
               small = pieces.slots[small_a].container->usable_area_mm2();
  ASSERT_NEAR(big, kRoomMm * kRoomMm, 0.01 * big);
  ASSERT_NEAR(small, kRoomMm * (kSmallMm - (kBigMm - kRoomMm)), 0.01 * small);
  const double pair_small = squares / (2 * big), pair_mixed = squares / (big + small);
  ASSERT_LT(pair_small, 0.7);
  ASSERT_GT(pair_mixed, 0.75);
  ASSERT_LT(pair_mixed, 0.8);
  const std::vector<int> used = {small_a, small_b, full};
  const MergeTurn first = merge_turn(instance, pieces, a.slot_of, used, 0, 0.8);
  EXPECT_EQ(first.first, small_a);
  EXPECT_EQ(first.second, small_b);
  EXPECT_EQ(first.spare, spare);
  EXPECT_NEAR(first.fill_after, pair_small, 1e-9);
  EXPECT_EQ(first.destinations, (std::vector<int>{full, spare}));
  // Turn 1: the next pair by fill, a small hide with the full one.
  const MergeTurn second = merge_turn(instance, pieces, a.slot_of, used, 1, 0.8);
  EXPECT_EQ(second.first, small_a);
  EXPECT_EQ(second.second, full);
  EXPECT_NEAR(second.fill_after, pair_mixed, 1e-9);
  // Below the mixed pairs' fill only the small pair is left, on every turn.
  EXPECT_EQ(merge_turn(instance, pieces, a.slot_of, used, 1, 0.7).second, small_b);
  EXPECT_EQ(merge_turn(instance, pieces, a.slot_of, used, 0, 0.5).first, -1);

  const Deadline deadline(60);
  ASSERT_TRUE(merge_hides(instance, pieces, options, deadline, a.slot_of, a.state, first, 1, EjectBudget{}));
  EXPECT_EQ(pieces_on(a, full), 4);
  EXPECT_EQ(pieces_on(a, spare), 2);
  EXPECT_EQ(pieces_on(a, small_a), 0);
  EXPECT_EQ(pieces_on(a, small_b), 0);
  const Layout layout = hide_layout(instance, pieces, a.slot_of, a.state, {});
  EXPECT_TRUE(check_layout(layout, instance).empty());
  EXPECT_EQ(used_bin_count(layout), 2);
  EXPECT_NEAR(layout.utilisation, squares / (2 * kBigMm * kBigMm), 1e-9);  // over the outlines
}

TEST(HideMerge, NoUnusedHideNoMerge) {
  NestInstance instance = merge_instance();
  instance.bins.resize(3);  // bins 0, 1 big, 2 small: all in use below
  NestOptions options;
  const HidePieces pieces = prepare_hide_pieces(instance, options);
  std::vector<int> slot_of = {0, 0, 1, 1, 2, 2};
  EXPECT_EQ(merge_turn(instance, pieces, slot_of, {2, 1, 0}, 0, 1.0).first, -1);
}

}  // namespace
}  // namespace lastcut
