// The ejection chain (engine/nest/hide_eject) on square hides whose answers follow from arithmetic:
// a hide is emptied into the gaps of another only after that one is separated (no free spot is
// left for the first piece, four squares fit only as a 2 x 2 block), a piece that needs a hide's
// room makes a small piece move on to a third hide (an ejection), and two hides that can only swap
// their pieces are rearranged, not emptied. Every result is checked by the independent layout checker.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/nest/hide_eject.hpp"
#include "engine/nest/layout_check.hpp"
#include "hide_assignment.hpp"
#include "nest_test_instances.hpp"

namespace lastcut {
namespace {

using namespace nest_detail;
using test::HideAssignment;
using test::pieces_on;
using test::put;

constexpr double kHideMm = 230, kGapMm = 2, kMarginMm = 5;
// The room a piece's inflated outline may use: the hide less (margin - gap/2) on each side.
constexpr double kRoomMm = kHideMm - 2 * (kMarginMm - kGapMm / 2);

NestInstance square_hides(int hides) { return test::square_hides(hides, kHideMm, kGapMm, kMarginMm); }

std::string problems_of(const NestInstance& instance, const HidePieces& pieces, const HideAssignment& a) {
  std::string text;
  for (const std::string& p : check_layout(hide_layout(instance, pieces, a.slot_of, a.state, {}), instance)) text += p + "; ";
  return text;
}

TEST(HideEject, EmptiesAHideIntoTheGapsOfAnotherBySeparatingIt) {
  // Four 100 mm squares (102 mm inflated) fit one hide only as a 2 x 2 block: 2 x 102 <= 222 < 3 x 102.
  static_assert(2 * (100 + kGapMm) <= kRoomMm && 3 * (100 + kGapMm) > kRoomMm);
  NestInstance instance = square_hides(2);
  instance.items.push_back(test::item(0, test::rectangle(100, 100), 4));
  NestOptions options;
  const HidePieces pieces = prepare_hide_pieces(instance, options);
  ASSERT_EQ(pieces.item_of.size(), 4u);
  HideAssignment a{std::vector<int>(4, -1), std::vector<PieceState>(4)};
  // Hide 0: two squares side by side at mid-height block both columns (60 mm free above and below).
  ASSERT_TRUE(put(pieces, a, 0, 0, 55, kHideMm / 2));
  ASSERT_TRUE(put(pieces, a, 1, 0, kHideMm - 55, kHideMm / 2));
  ASSERT_TRUE(put(pieces, a, 2, 1, 0, 0));
  ASSERT_TRUE(put(pieces, a, 3, 1, kHideMm, kHideMm));
  ASSERT_EQ(problems_of(instance, pieces, a), "");
  {  // No free spot is left on hide 0: a plain insertion cannot empty hide 1.
    HideAssignment probe = a;
    probe.slot_of[2] = -1;
    EXPECT_FALSE(put(pieces, probe, 2, 0, kHideMm / 2, kHideMm / 2));
  }
  const Deadline deadline(60);
  ASSERT_EQ(eject_hide(instance, pieces, options, deadline, a.slot_of, a.state, 1, {0}, 1, EjectBudget{}), EjectResult::Emptied);
  EXPECT_EQ(pieces_on(a, 0), 4);
  EXPECT_EQ(pieces_on(a, 1), 0);
  EXPECT_EQ(problems_of(instance, pieces, a), "");
}

TEST(HideEject, ASmallPieceMakesRoomByMovingOnToAThirdHide) {
  // Hide 0 holds a 110 x 215 slab and a 50 mm square; hide 2 a 165 mm square. The 100 x 215 slab of
  // hide 1 fits beside the 110 mm one (112 + 102 <= 222) but not with the 50 mm square too, and not on
  // hide 2 (167 + 102 > 222); the 50 mm square fits beside the 165 mm one (167 + 52 <= 222).
  static_assert(112 + 102 <= kRoomMm && 112 + 102 + 52 > kRoomMm && 167 + 102 > kRoomMm && 167 + 52 <= kRoomMm);
  NestInstance instance = square_hides(3);
  instance.items.push_back(test::item(0, test::rectangle(110, 215), 1, {0}));
  instance.items.push_back(test::item(1, test::rectangle(50, 50), 1, {0}));
  instance.items.push_back(test::item(2, test::rectangle(100, 215), 1, {0}));
  instance.items.push_back(test::item(3, test::rectangle(165, 165), 1, {0}));
  NestOptions options;
  const HidePieces pieces = prepare_hide_pieces(instance, options);
  ASSERT_EQ(pieces.item_of.size(), 4u);
  HideAssignment a{std::vector<int>(4, -1), std::vector<PieceState>(4)};
  ASSERT_TRUE(put(pieces, a, 0, 0, 0, kHideMm / 2));
  ASSERT_TRUE(put(pieces, a, 1, 0, kHideMm / 2 + 30, kHideMm / 2));
  ASSERT_TRUE(put(pieces, a, 2, 1, 0, kHideMm / 2));
  ASSERT_TRUE(put(pieces, a, 3, 2, 0, 0));
  ASSERT_EQ(problems_of(instance, pieces, a), "");
  // The dealing sends the slab to the hide with the most free area: hide 0 (more than hide 2).
  const double usable = pieces.slots[0].container->usable_area_mm2();
  ASSERT_GT(usable - 110 * 215 - 50 * 50, usable - 165 * 165);
  const Deadline deadline(60);
  {  // Without an ejection the chain cannot do it.
    HideAssignment b = a;
    EjectBudget no_ejection;
    no_ejection.max_ejections = 0;
    EXPECT_NE(eject_hide(instance, pieces, options, deadline, b.slot_of, b.state, 1, {0, 2}, 1, no_ejection), EjectResult::Emptied);
  }
  ASSERT_EQ(eject_hide(instance, pieces, options, deadline, a.slot_of, a.state, 1, {0, 2}, 1, EjectBudget{}), EjectResult::Emptied);
  EXPECT_EQ(a.slot_of, (std::vector<int>{0, 2, 0, 2}));
  EXPECT_EQ(problems_of(instance, pieces, a), "");
}

TEST(HideEject, TwoHidesThatCanOnlySwapAreRearrangedNotEmptied) {
  // A 200 mm square needs an empty hide (202 + 52 > 222); the other hide holds a 50 mm square and has
  // the area for it, so only the geometry says no.
  NestInstance instance = square_hides(2);
  instance.items.push_back(test::item(0, test::rectangle(200, 200), 1));
  instance.items.push_back(test::item(1, test::rectangle(50, 50), 1));
  NestOptions options;
  const HidePieces pieces = prepare_hide_pieces(instance, options);
  HideAssignment a{std::vector<int>(2, -1), std::vector<PieceState>(2)};
  ASSERT_TRUE(put(pieces, a, 0, 1, kHideMm / 2, kHideMm / 2));
  ASSERT_TRUE(put(pieces, a, 1, 0, kHideMm / 2, kHideMm / 2));
  ASSERT_GE(pieces.slots[0].container->usable_area_mm2() - 50 * 50, 200 * 200);
  const Deadline deadline(60);
  // The 200 mm square takes hide 0 only by ejecting the 50 mm one (2,500 mm^2, within 1.5 x its own
  // area), which may not go back to hide 0 and so ends on the emptied hide 1: a swap, no hide saved.
  EXPECT_EQ(eject_hide(instance, pieces, options, deadline, a.slot_of, a.state, 1, {0}, 1, EjectBudget{}), EjectResult::Rearranged);
  EXPECT_EQ(a.slot_of, (std::vector<int>{0, 1}));
  EXPECT_EQ(problems_of(instance, pieces, a), "");
}

TEST(HideEject, ReplacesABigHideByASmallerUnusedOne) {
  // Hides (opening order: largest first): 0 is 400 x 400 with two 100 mm squares, 1 is full (four
  // squares as a 2 x 2 block), 2 is an unused 230 x 130 hide that holds two squares side by side
  // (2 x 102 <= 222, 102 <= 130 - 8).
  NestInstance instance = square_hides(3);
  instance.bins[0].outer = test::rectangle(400, 400);
  instance.bins[2].outer = test::rectangle(kHideMm, 130);
  instance.items.push_back(test::item(0, test::rectangle(100, 100), 6));
  NestOptions options;
  const HidePieces pieces = prepare_hide_pieces(instance, options);
  ASSERT_EQ(pieces.slots[0].bin_index, 0);
  ASSERT_EQ(pieces.slots[2].bin_index, 2);
  HideAssignment a{std::vector<int>(6, -1), std::vector<PieceState>(6)};
  ASSERT_TRUE(put(pieces, a, 0, 0, 0, 0));
  ASSERT_TRUE(put(pieces, a, 1, 0, 400, 400));
  for (int k = 0; k < 4; ++k) ASSERT_TRUE(put(pieces, a, 2 + k, 1, k % 2 ? kHideMm : 0, k / 2 ? kHideMm : 0));
  ASSERT_EQ(problems_of(instance, pieces, a), "");
  // The turns: hide 0 then hide 1 as the target; the smaller hide 2 joins on the second round.
  EXPECT_EQ(eject_turn(instance, pieces, {0, 1}, 0, false).destinations, (std::vector<int>{1}));
  EXPECT_EQ(eject_turn(instance, pieces, {0, 1}, 1, false).target, 1);
  const EjectTurn replace = eject_turn(instance, pieces, {0, 1}, 2, false);
  EXPECT_EQ(replace.target, 0);
  EXPECT_EQ(replace.destinations, (std::vector<int>{1, 2}));
  EXPECT_EQ(eject_turn(instance, pieces, {0, 1}, 0, true).destinations, (std::vector<int>{1, 2}));
  const double used_before = hide_layout(instance, pieces, a.slot_of, a.state, {}).utilisation;
  const Deadline deadline(60);
  ASSERT_EQ(eject_hide(instance, pieces, options, deadline, a.slot_of, a.state, replace.target, replace.destinations, 1,
                       EjectBudget{}),
            EjectResult::Emptied);
  EXPECT_EQ(pieces_on(a, 0), 0);
  EXPECT_EQ(pieces_on(a, 1), 4);
  EXPECT_EQ(pieces_on(a, 2), 2);
  EXPECT_EQ(problems_of(instance, pieces, a), "");
  // Utilisation of the used hides: six squares over two 230 mm hides' areas instead of 400^2 + 230^2.
  EXPECT_NEAR(used_before, 6e4 / (400.0 * 400 + kHideMm * kHideMm), 1e-9);
  EXPECT_NEAR(hide_layout(instance, pieces, a.slot_of, a.state, {}).utilisation, 6e4 / (kHideMm * kHideMm + kHideMm * 130), 1e-9);
}

}  // namespace
}  // namespace lastcut
