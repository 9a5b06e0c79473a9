// The batch entry (engine/nest/hide_batch.hpp): rotations, priorities and pair groups set on the
// items, and whole jobs only in the layout: a job whose pieces do not all fit on one hide is
// taken out whole and the others nested again. Sizes are chosen so the outcome follows from areas
// alone, whatever the nester. The offcut against a closed form.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "engine/core/engine_error.hpp"
#include "engine/nest/hide_batch.hpp"
#include "engine/nest/hide_offcut.hpp"
#include "engine/nest/layout_check.hpp"

namespace lastcut {
namespace {

NestItem square(double side_mm) {
  NestItem item;
  item.shape.points = {{0, 0}, {side_mm, 0}, {side_mm, side_mm}, {0, side_mm}};
  return item;
}

Bin rectangle_hide(double w_mm, double h_mm) {
  Bin bin;
  bin.outer.points = {{0, 0}, {w_mm, 0}, {w_mm, h_mm}, {0, h_mm}};
  return bin;
}

TEST(HideBatch, ItemsCarryRotationsPriorityAndPairGroups) {
  std::vector<PieceGroup> groups = {{"J1", "100", 5, {square(10), square(20)}},
                                    {"J2", "100", 4, {square(10)}},
                                    {"J3", "", 3, {square(10)}}};
  BatchSpec spec;
  spec.rotation_step_deg = 120;
  spec.gap_mm = 2;
  spec.margin_mm = 3;
  const BatchInstance same = hide_batch(groups, {rectangle_hide(500, 400), rectangle_hide(300, 300)}, spec, "b");
  ASSERT_EQ(same.instance.items.size(), 4u);
  EXPECT_EQ(same.group_of_item, (std::vector<int>{0, 0, 1, 2}));
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(same.instance.items[i].id, static_cast<int>(i));
    EXPECT_EQ(same.instance.items[i].allowed_rotations_deg, (std::vector<double>{0, 120, 240}));
    EXPECT_EQ(same.instance.items[i].priority, groups[same.group_of_item[i]].priority);
  }
  EXPECT_EQ(same.instance.items[0].pair_group, "order 100");
  EXPECT_EQ(same.instance.items[2].pair_group, "order 100");
  EXPECT_EQ(same.instance.items[3].pair_group, "job J3");
  EXPECT_EQ(same.instance.bins[1].id, 1);
  EXPECT_EQ(same.instance.gap_mm, 2);
  EXPECT_EQ(same.instance.margin_mm, 3);
  spec.pairs = PairPolicy::Any;
  spec.rotation_step_deg = 0;
  const BatchInstance any = hide_batch(groups, {rectangle_hide(500, 400)}, spec, "b");
  EXPECT_EQ(any.instance.items[0].pair_group, "job J1");
  EXPECT_EQ(any.instance.items[2].pair_group, "job J2");
  EXPECT_TRUE(any.instance.items[0].allowed_rotations_deg.empty());
  const BatchInstance strip = strip_batch(groups, 800, spec, "s");
  EXPECT_EQ(strip.instance.strip_height, 800);
  EXPECT_TRUE(strip.instance.items[0].pair_group.empty());
  EXPECT_THROW(hide_batch(groups, {}, spec, "b"), EngineError);
  EXPECT_THROW(hide_batch({{"J9", "", 0, {}}}, {rectangle_hide(500, 400)}, spec, "b"), EngineError);
  spec.rotation_step_deg = 400;
  EXPECT_THROW(strip_batch(groups, 800, spec, "s"), EngineError);
}

TEST(HideBatch, AJobThatDoesNotFitWholeIsTakenOutWhole) {
  // A 300 x 300 hide holds one 250 mm square and nothing else (area 90000 < 2 x 62500). J1 has two
  // such squares: it can never be cut whole, so neither of its squares may stay in the layout; J2
  // (one square, lower priority) is what the hide is for.
  std::vector<PieceGroup> groups = {{"J1", "", 10, {square(250), square(250)}}, {"J2", "", 1, {square(250)}}};
  const BatchInstance batch = hide_batch(groups, {rectangle_hide(300, 300)}, BatchSpec{}, "whole");
  NestOptions options;
  options.time_limit_s = 0.5;
  options.iteration_limit = 20;
  const Layout layout = nest_batch(batch, options);
  EXPECT_TRUE(check_layout(layout, batch.instance).empty());
  std::map<int, int> placed_per_group;
  for (const Placement& p : layout.placements) ++placed_per_group[batch.group_of_item[static_cast<size_t>(p.item)]];
  EXPECT_EQ(placed_per_group.count(0), 0u) << "J1 partly cut";
  // J2 fits alone, so it is cut (J1 waits whatever the nester tried first).
  EXPECT_EQ(placed_groups(batch, layout), (std::vector<int>{1}));
  ASSERT_EQ(layout.placements.size(), 1u);
  int unplaced = 0;
  for (const Unplaced& u : layout.unplaced) unplaced += u.count;
  EXPECT_EQ(unplaced, 2);
  // Utilisation recomputed for what stays: placed area over the hide's area.
  EXPECT_NEAR(layout.utilisation, 62500.0 / 90000.0, 1e-9);
}

TEST(HideBatch, AJobThatMaySplitIsCutInPartAndTheOthersStayWhole) {
  // The same hide, and J1's two 250 mm squares and J2's one, all of one order: only one square fits.
  // Without splitting J1 waits whole (above); when J1 may split it joins no pair group, one of its
  // squares is cut, the other waits, and J2 (same order, lower priority) waits whole.
  std::vector<PieceGroup> groups = {{"J1", "7", 10, {square(250), square(250)}, true}, {"J2", "7", 1, {square(250)}}};
  const BatchInstance batch = hide_batch(groups, {rectangle_hide(300, 300)}, BatchSpec{}, "split");
  EXPECT_EQ(batch.instance.items[0].pair_group, "") << "a job that may split joins no pair";
  EXPECT_EQ(batch.instance.items[2].pair_group, "order 7");
  NestOptions options;
  options.time_limit_s = 0.5;
  options.iteration_limit = 20;
  const Layout layout = nest_batch(batch, options);
  EXPECT_TRUE(check_layout(layout, batch.instance).empty());
  ASSERT_EQ(layout.placements.size(), 1u);
  EXPECT_EQ(batch.group_of_item[static_cast<size_t>(layout.placements[0].item)], 0) << "J1, placed first, cut in part";
  EXPECT_TRUE(placed_groups(batch, layout).empty()) << "neither job is whole on the hide";
  int unplaced = 0;
  for (const Unplaced& u : layout.unplaced) unplaced += u.count;
  EXPECT_EQ(unplaced, 2);
}

TEST(HideBatch, OffcutIsTheHideMinusHolesAndGrownPieces) {
  // One 100 mm square placed by hand at (100, 100) on a 1000 x 600 hide with a 50 x 40 hole; gap 2 mm:
  // the grown square is 104 x 104 with rounded corners (area 100^2 + 4 * 100 * 2 + pi * 2^2).
  Bin hide = rectangle_hide(1000, 600);
  hide.holes.push_back({{{500, 300}, {550, 300}, {550, 340}, {500, 340}}});
  NestInstance instance;
  instance.bins = {hide};
  instance.items = {square(100)};
  instance.gap_mm = 2;
  Layout layout;
  layout.placements.push_back({0, 0, 0, 0, false, 100, 100});
  const Offcut offcut = hide_offcut(layout, instance, 0);
  const double grown = 100.0 * 100.0 + 4 * 100.0 * 2.0 + M_PI * 4.0;
  EXPECT_NEAR(offcut.area_mm2, 1000.0 * 600.0 - 50.0 * 40.0 - grown, 2.0);
  EXPECT_EQ(offcut.outers.size(), 1u);
  EXPECT_EQ(offcut.holes.size(), 2u);  // the defect and the cut piece, both inside the outline
  const std::string dxf = offcut_dxf(offcut);
  EXPECT_NE(dxf.find("OFFCUT_HOLE"), std::string::npos);
}

}  // namespace
}  // namespace lastcut
