// The independent checker refuses hand-made hide layouts that break exactly one constraint (inside
// the hide, clear of holes by the margin, quality zones per piece and per quality region, grain vs
// the hide's backbone, pair groups) and accepts the same layout with that one piece moved right.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/nest/layout_check.hpp"
#include "hide_test_instances.hpp"

namespace lastcut {
namespace {

bool mentions(const std::vector<std::string>& problems, const std::string& words) {
  for (const auto& p : problems)
    if (p.find(words) != std::string::npos) return true;
  return false;
}

std::string all(const std::vector<std::string>& problems) {
  std::string text;
  for (const auto& p : problems) text += p + "; ";
  return text;
}

// Only the given placements; every other copy is listed as unplaced.
std::vector<std::string> check(const NestInstance& instance, std::vector<Placement> placements) {
  Layout layout;
  layout.instance = instance.name;
  layout.placements = std::move(placements);
  for (const NestItem& item : instance.items) {
    int placed = 0;
    for (const Placement& p : layout.placements) placed += p.item == item.id ? 1 : 0;
    if (placed < item.demand) layout.unplaced.push_back({item.id, item.demand - placed, "test"});
  }
  update_utilisation(layout, instance);
  return check_layout(layout, instance);
}

// Item 0 turned along the 30 deg backbone: rotation 30 about its own origin, moved to (x, y).
Placement graded_at(double x, double y, double rotation_deg = 30) { return {0, 10, 0, rotation_deg, false, x, y}; }

TEST(NestHideCheck, GradedPieceAlongTheBackboneOnGoodLeatherIsAccepted) {
  const NestInstance instance = test::constraint_instance();
  const auto problems = check(instance, {graded_at(100, 60)});
  EXPECT_TRUE(problems.empty()) << all(problems);
}

TEST(NestHideCheck, RefusesAPieceOutsideTheHideOrOnItsMargin) {
  const NestInstance instance = test::constraint_instance();
  EXPECT_TRUE(mentions(check(instance, {graded_at(-30, 60)}), "sticks out of hide 10"));
  // The lower edge runs from (0, 30) to (300, 0): the corner (50, 27) of a filler is 1.99 mm from it
  // (margin 5), the corner (50, 35) 9.95 mm.
  const Placement filler_low{3, 10, 0, 0, false, 50, 27};
  EXPECT_TRUE(mentions(check(instance, {filler_low}), "sticks out of hide 10 (margin included)"));
  const Placement filler_ok{3, 10, 0, 0, false, 50, 35};
  EXPECT_TRUE(check(instance, {filler_ok}).empty()) << all(check(instance, {filler_ok}));
}

TEST(NestHideCheck, RefusesAPieceWithinTheMarginOfAHole) {
  const NestInstance instance = test::constraint_instance();
  // The hole spans x 280..330: a filler ending at x 277 is 3 mm from it (margin 5); at 270 it is 10 mm.
  EXPECT_TRUE(mentions(check(instance, {{3, 10, 0, 0, false, 217, 190}}), "covers defect 0 of hide 10"));
  EXPECT_TRUE(check(instance, {{3, 10, 0, 0, false, 210, 190}}).empty());
}

TEST(NestHideCheck, RefusesAPieceOrItsQualityRegionOnPoorLeather) {
  NestInstance instance = test::constraint_instance();
  // Along the backbone the graded piece's region (own x 80..120) ends up upper right. Unrotated
  // placements keep the geometry obvious, so here the grain has no tolerance issue: a 0 deg backbone.
  instance.bins[0].backbone_deg = 0;
  // The belly (quality 1) starts at y 300. Region at own x 80..120: piece at (100, 260) reaches y 310
  // with all of it, region included.
  const auto region_on_belly = check(instance, {{0, 10, 0, 0, false, 100, 260}});
  EXPECT_TRUE(mentions(region_on_belly, "its quality region 0 lies on zone 0 of quality 1 but needs 2")) << all(region_on_belly);
  // Rotated 180 deg about its origin the region is at x -120..-80 of the piece; put the piece so that
  // only the part without the region (own x 0..80 -> placed x - 80..x) touches the belly: a zone
  // polygon covering only x <= 300 and the region beyond x 300.
  instance.bins[0].zones[0].shape = Polygon2{{{0, 300}, {300, 300}, {300, 420}, {0, 420}}};
  // Unrotated at (230, 260): the piece spans x 230..350, its region x 310..350: only the plain part lies
  // on the zone, which the piece (min_quality 0) may.
  EXPECT_TRUE(check(instance, {{0, 10, 0, 0, false, 230, 260}}).empty()) << all(check(instance, {{0, 10, 0, 0, false, 230, 260}}));
  // A whole-piece requirement is checked as before.
  instance.items[0].min_quality = 2;
  EXPECT_TRUE(mentions(check(instance, {{0, 10, 0, 0, false, 230, 260}}), "lies on zone 0 of quality 1 but needs 2"));
}

TEST(NestHideCheck, RefusesGrainAcrossTheBackbone) {
  const NestInstance instance = test::constraint_instance();
  const auto along_x = check(instance, {graded_at(100, 60, 0)});  // x axis, 30 deg off the backbone
  EXPECT_TRUE(mentions(along_x, "grain is 30 deg off the material's grain (tolerance 5)")) << all(along_x);
  EXPECT_TRUE(check(instance, {graded_at(200, 160, 210)}).empty());  // reversed along the backbone is fine
  EXPECT_TRUE(mentions(check(instance, {graded_at(100, 60, 36)}), "grain is 6 deg off"));
  // Without a backbone the x axis is the grain again.
  NestInstance plain = instance;
  plain.bins[0].backbone_deg.reset();
  EXPECT_TRUE(check(plain, {graded_at(100, 60, 0)}).empty());
}

TEST(NestHideCheck, RefusesPairsSplitApartOrHalfPlaced) {
  const NestInstance two = test::constraint_instance(2);
  const Placement left{1, 10, 0, 0, false, 60, 100};
  // The L's centroid lies 34.17 mm from its leg's outer side: the mirrored piece above the first one
  // (x 60..150, y 175..245) has its centroid sqrt(21.7^2 + 75^2) = 78 mm away.
  const Placement right_near{2, 10, 0, 0, false, 150, 175};
  const auto near = check(two, {left, right_near});
  EXPECT_TRUE(near.empty()) << all(near);
  // The bound: mean diagonal of the two L shapes (both hypot(90, 70)) plus the gap.
  const double bound = std::hypot(90.0, 70.0) + 2;
  const Placement right_far{2, 10, 0, 0, false, 60 + 90 + bound + 40, 100};
  EXPECT_TRUE(mentions(check(two, {left, right_far}), "is not near another piece of its group"));
  const Placement right_other_hide{2, 11, 0, 0, false, 150, 175};
  EXPECT_TRUE(mentions(check(two, {left, right_other_hide}), "is on another hide"));
  EXPECT_TRUE(mentions(check(two, {left}), "1 of its 2 pieces placed (all or none)"));
  EXPECT_TRUE(check(two, {}).empty());  // none placed is allowed
  NestInstance wide = two;
  wide.pair_distance_mm = 1000;  // configurable "near"
  EXPECT_TRUE(check(wide, {left, right_far}).empty());
}

}  // namespace
}  // namespace lastcut
