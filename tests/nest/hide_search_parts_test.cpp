// Two parts of the hide search with a contract of their own: the schedule of moves
// (engine/nest/hide_schedule: which move runs on which attempt, and the turn it starts from) and the
// search state (engine/nest/hide_search_state: the cached areas follow every change, and the
// objective is one comparison: placed area, then hides, then leather, then concentration).
#include <gtest/gtest.h>

#include <vector>

#include "engine/nest/hide_schedule.hpp"
#include "engine/nest/hide_search_state.hpp"
#include "hide_assignment.hpp"
#include "nest_test_instances.hpp"

namespace lastcut {
namespace {

using namespace nest_detail;

bool is_chain(MoveId move) { return move == MoveId::Eject || move == MoveId::Merge; }

TEST(HideSchedule, EveryOtherStepIsAChainOnEveryTable) {
  for (bool at_bound : {false, true})
    for (int level : {0, 1, 2})
      for (long step = 0; step < 48; ++step)
        EXPECT_EQ(is_chain(scheduled_move(step, level, at_bound).move), step % 2 == 1)
            << "step " << step << " level " << level << (at_bound ? " at the area bound" : "");
}

TEST(HideSchedule, EveryThirdChainIsAMergeButAtTheAreaBound) {
  for (int level : {0, 1, 2}) {
    std::vector<MoveId> chains;
    for (long step = 1; step < 48; step += 2) chains.push_back(scheduled_move(step, level, false).move);
    for (size_t c = 0; c < chains.size(); ++c) EXPECT_EQ(chains[c], c % 3 == 2 ? MoveId::Merge : MoveId::Eject) << c;
  }
  for (long step = 0; step < 48; ++step) EXPECT_NE(scheduled_move(step, 1, true).move, MoveId::Merge);
}

TEST(HideSchedule, LevelZeroOnlyMovesFromLevelOneMoveSwapRepackShrinkInTurn) {
  for (long step = 0; step < 48; step += 2) {
    const ScheduledMove first = scheduled_move(step, 0, false);
    EXPECT_EQ(first.move, MoveId::Move);
    EXPECT_EQ(first.turn, step / 2) << "level 0: the units of the hide in turn";
  }
  const MoveId cycle[] = {MoveId::Move, MoveId::Swap, MoveId::Repack, MoveId::Shrink};
  for (long step = 0; step < 48; step += 2) EXPECT_EQ(scheduled_move(step, 2, false).move, cycle[(step / 2) % 4]) << step;
  // At the area bound: shrinks only (and chains), each the next pair of hides.
  for (long step = 0; step < 48; step += 2) {
    EXPECT_EQ(scheduled_move(step, 1, true).move, MoveId::Shrink);
    EXPECT_EQ(scheduled_move(step, 1, true).turn, step / 2);
  }
}

TEST(HideSchedule, ShrinksMergesAndChainsCountTheirOwnTurns) {
  // The k-th shrink, merge or (off the bound) ejection chain since the last success takes turn k.
  for (MoveId move : {MoveId::Shrink, MoveId::Merge, MoveId::Eject}) {
    long seen = 0;
    for (long step = 0; step < 96; ++step) {
      const ScheduledMove next = scheduled_move(step, 1, false);
      if (next.move == move) {
        EXPECT_EQ(next.turn, seen++) << step;
      }
    }
    EXPECT_GT(seen, 5);
  }
}

class HideSearchStateTest : public ::testing::Test {
 protected:
  // Two hides 300 x 300 and one 200 x 200; four squares 100 x 100, one unit each.
  HideSearchStateTest() : instance_(make_instance()), pieces_(prepare_hide_pieces(instance_, NestOptions{})) {
    for (int slot = 0; slot < 3; ++slot)
      (pieces_.slots[slot].container->usable_area_mm2() < 50000 ? small_ : big_).push_back(slot);
  }
  static NestInstance make_instance() {
    NestInstance instance = test::square_hides(3, 300, 2, 5);
    instance.bins[2].outer = test::rectangle(200, 200);
    instance.items = {test::item(0, test::rectangle(100, 100), 4)};
    return instance;
  }
  HideSearchState state(std::vector<int> slot_of) const {
    return HideSearchState(pieces_, HidePlacement{slot_of, std::vector<PieceState>(slot_of.size())});
  }

  NestInstance instance_;
  HidePieces pieces_;
  std::vector<int> big_, small_;  // slots
};

TEST_F(HideSearchStateTest, TheHidesAreAsMeant) {
  ASSERT_EQ(pieces_.units.size(), 4u);
  ASSERT_EQ(big_.size(), 2u);
  ASSERT_EQ(small_.size(), 1u);
}

TEST_F(HideSearchStateTest, MorePlacedAreaBeatsFewerHides) {
  const int a = big_[0], b = big_[1];
  EXPECT_TRUE(state({a, a, b, b}).better_than(state({a, a, a, -1})));
  EXPECT_FALSE(state({a, a, a, -1}).better_than(state({a, a, b, b})));
}

TEST_F(HideSearchStateTest, ThenFewerHidesThenLessLeather) {
  const int a = big_[0], b = big_[1], c = small_[0];
  EXPECT_TRUE(state({a, a, a, a}).better_than(state({a, a, c, c})));
  EXPECT_TRUE(state({c, c, c, c}).better_than(state({a, a, a, a})));
  EXPECT_TRUE(state({a, a, c, c}).better_than(state({a, a, b, b})));
}

TEST_F(HideSearchStateTest, ThenTheMoreConcentratedAndNeverItself) {
  const int a = big_[0], b = big_[1];
  const HideSearchState three_one = state({a, a, a, b}), two_two = state({a, a, b, b});
  EXPECT_GT(three_one.concentration(), two_two.concentration());
  EXPECT_TRUE(three_one.better_than(two_two));
  EXPECT_FALSE(two_two.better_than(three_one));
  EXPECT_FALSE(two_two.better_than(two_two));
}

TEST_F(HideSearchStateTest, TheCachedAreasFollowEveryChange) {
  const int a = big_[0], b = big_[1];
  HideSearchState s = state({a, a, b, -1});
  const double unit = pieces_.unit_area_mm2[0];
  EXPECT_DOUBLE_EQ(s.placed_area_mm2(a), 2 * unit);
  EXPECT_EQ(s.used_slots(), (std::vector<int>{std::min(a, b), std::max(a, b)}));
  EXPECT_EQ(s.targets().front(), b) << "the least filled first";
  s.take_off(pieces_.unit_of[2]);
  EXPECT_DOUBLE_EQ(s.placed_area_mm2(b), 0);
  EXPECT_EQ(s.used_slots(), std::vector<int>{a});
  s.edit().slot_of[3] = b;
  EXPECT_DOUBLE_EQ(s.placed_area_mm2(b), unit);
  EXPECT_DOUBLE_EQ(s.free_area_mm2(b), s.usable_area_mm2(b) - unit);
  EXPECT_DOUBLE_EQ(s.fill(a), 2 * unit / s.usable_area_mm2(a));
  EXPECT_TRUE(s.any_left_over());
}

}  // namespace
}  // namespace lastcut
