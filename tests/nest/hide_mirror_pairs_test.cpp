// A pair's pieces mirrored about the hide's backbone (engine/nest/hide_mirror_pairs.hpp). The oracle is
// the reflection itself, computed here point by point (c + 2 ((w - c).u) u - (w - c) for the line
// through c along u), and the independent layout checker: a piece moved onto the mirror image of its
// other foot's copy lies exactly on the reflected outline, and only where the hide passes the checker;
// a pair whose mirror places are taken moves to a free place; where none exists, nothing moves.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/nest/hide_batch.hpp"
#include "engine/nest/hide_mirror_pairs.hpp"
#include "engine/nest/layout_check.hpp"

namespace lastcut {
namespace {

// An L-shaped piece, no symmetry of its own, and its other foot's copy (x -> -x, then shifted by `d`).
NestItem l_piece(int id) {
  NestItem item;
  item.id = id;
  item.shape.points = {{0, 0}, {80, 0}, {80, 20}, {25, 20}, {25, 50}, {0, 50}};
  item.mirror_key = "vamp";
  return item;
}

NestItem other_foot(const NestItem& piece, int id, const Point2& d) {
  NestItem twin = piece;
  twin.id = id;
  for (Point2& p : twin.shape.points) p = Point2(-p.x(), p.y()) + d;
  make_counter_clockwise(twin.shape);
  return twin;
}

Bin hide_with_backbone(double backbone_deg, const Point2& through) {
  Bin bin;
  bin.outer.points = {{0, 0}, {600, 0}, {600, 300}, {0, 300}};
  bin.backbone_deg = backbone_deg;
  bin.backbone_point = through;
  return bin;
}

Point2 reflect(const Point2& w, const Point2& c, double line_deg) {
  const Point2 u(std::cos(line_deg * std::numbers::pi / 180), std::sin(line_deg * std::numbers::pi / 180));
  const Point2 r = w - c;
  return c + 2 * r.dot(u) * u - r;
}

// The largest distance from a point of `placed` to the nearest point of `target`.
double farthest_from(const Polygon2& placed, const std::vector<Point2>& target) {
  double worst = 0;
  for (const Point2& p : placed.points) {
    double nearest = 1e9;
    for (const Point2& q : target) nearest = std::min(nearest, (p - q).norm());
    worst = std::max(worst, nearest);
  }
  return worst;
}

TEST(HideMirrorPairs, TheMirrorPoseLaysTheTwinOnTheReflectedOutline) {
  const NestItem piece = l_piece(0);
  const NestItem twin = other_foot(piece, 1, {7, -3});
  for (const double backbone : {0.0, 30.0, -75.0}) {
    const Bin hide = hide_with_backbone(backbone, {250, 140});
    const Placement pose{0, 0, 0, 40, false, 120, 80};
    const Placement mirrored = mirrored_pose(piece, pose, twin, hide);
    std::vector<Point2> reflected;
    for (const Point2& w : placed_shape(piece, pose).points) reflected.push_back(reflect(w, {250, 140}, backbone));
    EXPECT_LT(farthest_from(placed_shape(twin, mirrored), reflected), 1e-9) << backbone;
    EXPECT_EQ(mirrored.item, 1);
    EXPECT_FALSE(mirrored.mirrored) << "a turn of the twin, never a flip";
  }
}

TEST(HideMirrorPairs, ATwinGoesOntoTheMirrorImageElseWithItsPairToAFreeMirroredPlaceElseStays) {
  // A 600 x 300 hide, its backbone along x through its middle; the vamp above the backbone at the
  // left, its twin at the right. A third piece C sits under the vamp at its mirror place, the second
  // time: then neither piece can move.
  NestInstance instance;
  instance.bins = {hide_with_backbone(0, {300, 150})};
  instance.gap_mm = 2;
  instance.margin_mm = 3;
  instance.items = {l_piece(0), other_foot(l_piece(0), 1, {0, 0})};
  Layout layout;
  layout.placements = {{0, 0, 0, 0, false, 40, 190}, {1, 0, 0, 0, false, 520, 190}};
  update_utilisation(layout, instance);
  ASSERT_TRUE(check_layout(layout, instance).empty());
  EXPECT_EQ(count_mirrored_pairs(layout, instance).pairs, 1);
  EXPECT_EQ(count_mirrored_pairs(layout, instance).mirrored, 0);
  const double utilisation = layout.utilisation;
  const MirroredPairs after = mirror_pairs_about_backbone(layout, instance);
  EXPECT_EQ(after.pairs, 1);
  EXPECT_EQ(after.mirrored, 1);
  EXPECT_TRUE(check_layout(layout, instance).empty());
  update_utilisation(layout, instance);
  EXPECT_DOUBLE_EQ(layout.utilisation, utilisation);
  std::vector<Point2> reflected;
  for (const Point2& w : placed_shape(instance.items[0], layout.placements[0]).points) reflected.push_back(reflect(w, {300, 150}, 0));
  EXPECT_LT(farthest_from(placed_shape(instance.items[1], layout.placements[1]), reflected), 1e-9);

  // C (a 100 mm square, twice) covers the mirror places of both pieces: the pair moves, both pieces, to
  // a free place where they lie mirrored; the squares stay.
  NestItem blocker;
  blocker.id = 2;
  blocker.demand = 2;
  blocker.shape.points = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  instance.items.push_back(blocker);
  Layout blocked;
  blocked.placements = {{0, 0, 0, 0, false, 40, 190}, {1, 0, 0, 0, false, 520, 190}, {2, 0, 0, 0, false, 20, 5},
                        {2, 0, 0, 0, false, 470, 5}};
  update_utilisation(blocked, instance);
  ASSERT_TRUE(check_layout(blocked, instance).empty());
  EXPECT_EQ(mirror_pairs_about_backbone(blocked, instance).mirrored, 1);
  EXPECT_TRUE(check_layout(blocked, instance).empty());
  EXPECT_EQ(blocked.placements[2].x, 20);
  EXPECT_EQ(blocked.placements[3].x, 470);
  reflected.clear();
  for (const Point2& w : placed_shape(instance.items[0], blocked.placements[0]).points) reflected.push_back(reflect(w, {300, 150}, 0));
  EXPECT_LT(farthest_from(placed_shape(instance.items[1], blocked.placements[1]), reflected), 1e-9);

  // Leather below grade 1 under the whole backbone's lower side: no mirror place exists, nothing moves.
  instance.items.pop_back();
  for (NestItem& item : instance.items) item.min_quality = 1;
  instance.bins[0].zones.push_back({Polygon2{{{0, 0}, {600, 0}, {600, 150}, {0, 150}}}, 0});
  Layout one_side;
  one_side.placements = {{0, 0, 0, 0, false, 40, 190}, {1, 0, 0, 0, false, 520, 190}};
  update_utilisation(one_side, instance);
  ASSERT_TRUE(check_layout(one_side, instance).empty());
  EXPECT_EQ(mirror_pairs_about_backbone(one_side, instance).mirrored, 0);
  EXPECT_EQ(one_side.placements[0].x, 40);
  EXPECT_EQ(one_side.placements[0].y, 190);
  EXPECT_EQ(one_side.placements[1].x, 520);
  EXPECT_EQ(one_side.placements[1].y, 190);
}

TEST(HideMirrorPairs, TheBatchMirrorsAPairsPiecesOnAHideWithABackbone) {
  // Two jobs of one order: each the vamp for both feet. The hide has room for all four.
  NestItem vamp = l_piece(0);
  std::vector<PieceGroup> groups = {{"J1", "9", 2, {vamp, other_foot(vamp, 1, {0, 0})}},
                                    {"J2", "9", 1, {vamp, other_foot(vamp, 1, {0, 0})}}};
  BatchSpec spec;
  spec.rotation_step_deg = 0;
  spec.gap_mm = 2;
  spec.margin_mm = 3;
  const BatchInstance batch = hide_batch(groups, {hide_with_backbone(0, {300, 150})}, spec, "mirror");
  EXPECT_EQ(batch.instance.items[0].mirror_key, "job J1: vamp");
  EXPECT_EQ(batch.instance.items[3].mirror_key, "job J2: vamp");
  NestOptions options;
  options.time_limit_s = 0.5;
  options.iteration_limit = 20;
  const Layout layout = nest_batch(batch, options);
  ASSERT_EQ(layout.placements.size(), 4u);
  EXPECT_TRUE(check_layout(layout, batch.instance).empty());
  const MirroredPairs pairs = count_mirrored_pairs(layout, batch.instance);
  EXPECT_EQ(pairs.pairs, 2);
  EXPECT_EQ(pairs.mirrored, 2) << "room enough: both pairs mirrored about the backbone";
  // The oracle: each job's other foot lies on the reflection of its first foot.
  const auto placed = [&](int id) {
    for (const Placement& p : layout.placements)
      if (p.item == id) return placed_shape(batch.instance.items[static_cast<std::size_t>(id)], p);
    return Polygon2{};
  };
  for (const int first : {0, 2}) {
    std::vector<Point2> reflected;
    for (const Point2& w : placed(first).points) reflected.push_back(reflect(w, {300, 150}, 0));
    EXPECT_LT(farthest_from(placed(first + 1), reflected), 1e-6) << "job " << first / 2 + 1;
  }
}

}  // namespace
}  // namespace lastcut
