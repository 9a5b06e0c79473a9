// The regrouping (engine/nest/hide_regroup) on square hides whose answers follow from arithmetic: the
// worst-fit start puts a square beside a full-width strip where it cannot lie, and the search has to
// find the one grouping that packs (the two strips together, the squares together). Results are checked
// by the independent layout checker; a grouping that cannot exist is reported as none.
#include <gtest/gtest.h>

#include <set>

#include "engine/nest/hide_regroup.hpp"
#include "engine/nest/hide_search.hpp"
#include "engine/nest/layout_check.hpp"
#include "hide_assignment.hpp"
#include "nest_test_instances.hpp"

namespace lastcut {
namespace {

using namespace nest_detail;

constexpr double kSideMm = 230, kGapMm = 2, kMarginMm = 5;
// The room a piece's inflated outline may use: the hide less (margin - gap/2) on each side.
constexpr double kRoomMm = kSideMm - 2 * (kMarginMm - kGapMm / 2);

NestOptions round_budget() {
  NestOptions options;
  options.iteration_limit = 40;  // deterministic: the oracle runs on rounds, not on time
  options.threads = 1;
  return options;
}

TEST(HideRegroup, FindsTheOnlyGroupingThatPacksWhereWorstFitFails) {
  // Strips 216 x 105 span a hide's width: two stack (2 x 107 <= 222), but nothing 150 tall goes beside one
  // (107 + 152 > 222, and 218 + 62 > 222 across). The square 150 and the square 60 share a hide (152 + 62 <= 222).
  static_assert(2 * (105 + kGapMm) <= kRoomMm && (105 + kGapMm) + (150 + kGapMm) > kRoomMm);
  static_assert((150 + kGapMm) + (60 + kGapMm) <= kRoomMm && 216 + kGapMm <= kRoomMm && 216 + kGapMm + 60 + kGapMm > kRoomMm);
  NestInstance instance = test::square_hides(2, kSideMm, kGapMm, kMarginMm);
  instance.items = {test::item(0, test::rectangle(216, 105), 2), test::item(1, test::rectangle(150, 150), 1),
                    test::item(2, test::rectangle(60, 60), 1)};
  const NestOptions options = round_budget();
  const HidePieces pieces = prepare_hide_pieces(instance, options);
  ASSERT_EQ(pieces.units.size(), 4u);
  // Worst fit by fill, largest first: strip, strip, then the big square beside a strip (92 % by area).
  const std::vector<int> placed(4, 0);
  const Deadline deadline(120);
  const auto found = regroup_onto(instance, pieces, options, placed, {0, 1}, deadline, RegroupBudget{}, 7, search_hide_placement);
  ASSERT_TRUE(found.has_value());
  EXPECT_TRUE(check_layout(hide_layout(instance, pieces, found->slot_of, found->state, {}), instance).empty());
  std::set<int> strips, squares;
  for (size_t p = 0; p < pieces.item_of.size(); ++p) {
    ASSERT_GE(found->slot_of[p], 0) << "piece " << p << " left over";
    (pieces.item_of[p] == 0 ? strips : squares).insert(found->slot_of[p]);
  }
  EXPECT_EQ(strips.size(), 1u) << "both strips on one hide";
  EXPECT_EQ(squares.size(), 1u) << "both squares on one hide";
  EXPECT_NE(*strips.begin(), *squares.begin());
}

TEST(HideRegroup, ReportsNoneWhenNoGroupingPacks) {
  // Three 150 mm squares onto one hide that holds one (2 x 152 > 222).
  static_assert(2 * (150 + kGapMm) > kRoomMm);
  NestInstance instance = test::square_hides(2, kSideMm, kGapMm, kMarginMm);
  instance.items = {test::item(0, test::rectangle(150, 150), 3)};
  const NestOptions options = round_budget();
  const HidePieces pieces = prepare_hide_pieces(instance, options);
  const Deadline deadline(120);
  EXPECT_FALSE(regroup_onto(instance, pieces, options, std::vector<int>(3, 0), {0}, deadline, RegroupBudget{}, 7, search_hide_placement));
  // Units left over in the layout given stay left over: two squares onto two hides is a grouping.
  const auto two = regroup_onto(instance, pieces, options, {0, 1, -1}, {0, 1}, deadline, RegroupBudget{}, 7, search_hide_placement);
  ASSERT_TRUE(two.has_value());
  EXPECT_EQ(two->slot_of[2], -1);
  EXPECT_NE(two->slot_of[0], two->slot_of[1]);
  EXPECT_TRUE(check_layout(hide_layout(instance, pieces, two->slot_of, two->state, {{0, 1, "left over"}}), instance).empty());
}

}  // namespace
}  // namespace lastcut
