// Pattern pieces as nest items (engine/nest/pattern_items.hpp): demand, mirrored twins, notches,
// internal and sew lines as drawn lines, grain and leather rules, the refusals; and the hide batch
// keeping a piece's own grain, so a vamp's grain line (not its x axis) is what lies along the
// backbone. The grain of a placed piece is checked on the layout by the independent checker
// (layout_check.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/engine_error.hpp"
#include "engine/nest/hide_batch.hpp"
#include "engine/nest/layout_check.hpp"
#include "engine/nest/pattern_items.hpp"

namespace lastcut {
namespace {

// A 100 x 40 mm piece with one notch on its bottom edge and a grain line at 30 degrees.
PatternPiece vamp_piece() {
  PatternPiece piece;
  piece.name = "vamp";
  piece.size = "42";
  piece.category = "upper leather";
  piece.quantity = 2;
  piece.cut_line_mm = {{0, 0}, {100, 0}, {100, 40}, {0, 40}};
  piece.notches = {{{30, 0}, {0, 1}}};
  piece.grain_line_mm = std::array<Point2, 2>{Point2(10, 10), Point2(10 + std::sqrt(3.0), 11)};
  return piece;
}

std::string refusal(const std::vector<PatternPiece>& pieces, const PatternNestSpec& spec) {
  try {
    items_from_pattern(pieces, spec);
  } catch (const EngineError& error) {
    return error.what();
  }
  return "";
}

TEST(PatternItems, DemandTwinsNotchesAndGrain) {
  PatternNestSpec spec;
  spec.sets = 3;
  spec.mirrored_twins = true;
  spec.rules = [](const PatternPiece&) { return PieceRules{10.0, 2}; };
  const std::vector<NestItem> items = items_from_pattern({vamp_piece()}, spec);
  ASSERT_EQ(items.size(), 2u);
  for (const NestItem& item : items) {
    EXPECT_EQ(item.demand, 6);
    EXPECT_NEAR(signed_area(item.shape), 4000, 1e-9);  // counter-clockwise, mirrored or not
    EXPECT_EQ(item.min_quality, 2);
    EXPECT_EQ(item.grain_tolerance_deg, 10);
    ASSERT_EQ(item.marks.size(), 1u);
    EXPECT_NEAR(item.marks[0].to_mm.y() - item.marks[0].from_mm.y(), 3, 1e-12);  // 3 mm into the piece
  }
  EXPECT_EQ(items[0].label, "vamp 42");
  EXPECT_EQ(items[1].label, "vamp 42 (other foot)");
  EXPECT_NEAR(*items[0].grain_deg, 30, 1e-9);
  EXPECT_NEAR(*items[1].grain_deg, 150, 1e-9);  // mirrored about the y axis
  EXPECT_NEAR(items[1].marks[0].from_mm.x(), -30, 1e-12);
  EXPECT_EQ(items[0].mirror_key, "0 vamp") << "the two feet's copies of one piece share a key";
  EXPECT_EQ(items[1].mirror_key, items[0].mirror_key);
  spec.mirrored_twins = false;
  EXPECT_EQ(items_from_pattern({vamp_piece()}, spec)[0].mirror_key, "") << "one foot: no twin";
}

TEST(PatternItems, InternalLinesAreDrawnLinesSewLinesWhenAsked) {
  PatternPiece piece = vamp_piece();
  piece.internal_lines_mm = {{{5, 5}, {95, 5}, {95, 35}, {5, 5}}};  // closed: first point repeated
  piece.sew_lines_mm = {{{2, 2}, {98, 2}}};
  PatternNestSpec spec;
  spec.mirrored_twins = true;
  std::vector<NestItem> items = items_from_pattern({piece}, spec);
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[0].drawn_lines_mm, piece.internal_lines_mm) << "the sew lines only when asked";
  ASSERT_EQ(items[1].drawn_lines_mm.size(), 1u);
  const std::vector<Point2> mirrored = {{-5, 5}, {-95, 5}, {-95, 35}, {-5, 5}};
  EXPECT_EQ(items[1].drawn_lines_mm[0], mirrored) << "the twin's lines mirrored with its outline";
  spec.draw_sew_lines = true;
  items = items_from_pattern({piece}, spec);
  ASSERT_EQ(items[0].drawn_lines_mm.size(), 2u);
  EXPECT_EQ(items[0].drawn_lines_mm[1], piece.sew_lines_mm[0]);
  EXPECT_EQ(items[1].drawn_lines_mm[1], (std::vector<Point2>{{-2, 2}, {-98, 2}}));
}

TEST(PatternItems, GrainFreeWithoutRuleOrLine) {
  PatternPiece lining = vamp_piece();
  lining.name = "lining";
  EXPECT_FALSE(items_from_pattern({lining}, {}).front().grain_deg);  // no rules: free
  lining.grain_line_mm.reset();
  PatternNestSpec spec;
  spec.rules = [](const PatternPiece&) { return PieceRules{10.0, 0}; };
  EXPECT_FALSE(items_from_pattern({lining}, spec).front().grain_deg);  // no grain line: free
}

TEST(PatternItems, Refusals) {
  EXPECT_EQ(refusal({}, {}), "no pattern pieces to nest");
  PatternNestSpec none;
  none.sets = 0;
  EXPECT_EQ(refusal({vamp_piece()}, none), "at least one set of the pattern pieces is needed");
  PatternPiece flat = vamp_piece();
  flat.cut_line_mm = {{0, 0}, {100, 0}, {50, 0}};
  EXPECT_EQ(refusal({flat}, {}), "piece \"vamp\": its cut line encloses no area");
  PatternPiece zero = vamp_piece();
  zero.quantity = 0;
  EXPECT_EQ(refusal({zero}, {}), "piece \"vamp\": quantity 0 is not a positive count");
  PatternNestSpec wide;
  wide.rules = [](const PatternPiece&) { return PieceRules{95.0, 0}; };
  EXPECT_EQ(refusal({vamp_piece()}, wide), "piece \"vamp\": a grain tolerance must be 0..90 deg");
  PatternPiece dot = vamp_piece();
  dot.internal_lines_mm = {{{5, 5}, {6, 6}}, {{7, 7}}};
  EXPECT_EQ(refusal({dot}, {}), "piece \"vamp\": internal line 2 has 1 point(s), a drawn line needs at least 2");
  dot.internal_lines_mm.clear();
  dot.sew_lines_mm = {{}};
  EXPECT_EQ(refusal({dot}, {}), "") << "sew lines not drawn are not looked at";
  PatternNestSpec sewn;
  sewn.draw_sew_lines = true;
  EXPECT_EQ(refusal({dot}, sewn), "piece \"vamp\": sew line 1 has 0 point(s), a drawn line needs at least 2");
}

Bin hide_with_backbone(double backbone_deg) {
  Bin bin;
  bin.outer.points = {{0, 0}, {600, 0}, {600, 500}, {0, 500}};
  bin.backbone_deg = backbone_deg;
  return bin;
}

TEST(PatternItems, HideBatchKeepsThePiecesOwnGrain) {
  PatternNestSpec rules;
  rules.rules = [](const PatternPiece&) { return PieceRules{5.0, 0}; };
  std::vector<NestItem> items = items_from_pattern({vamp_piece()}, rules);
  NestItem mold;  // a mold: no grain of its own, its x axis is heel to toe
  mold.shape.points = {{0, 0}, {80, 0}, {80, 30}, {0, 30}};
  items.push_back(mold);
  BatchSpec spec;
  spec.rotation_step_deg = 90;
  spec.grain_tolerance_deg = 20;
  const BatchInstance batch = hide_batch({{"J1", "", 0, items}}, {hide_with_backbone(90)}, spec, "b");
  // The vamp turns freely within its tolerance (no step of 90 deg puts a 30 deg grain along the
  // backbone); the mold in the material's steps.
  EXPECT_TRUE(batch.instance.items[0].allowed_rotations_deg.empty());
  EXPECT_EQ(batch.instance.items[1].allowed_rotations_deg, (std::vector<double>{0, 90, 180, 270}));
  EXPECT_NEAR(*batch.instance.items[0].grain_deg, 30, 1e-9);
  EXPECT_EQ(batch.instance.items[0].grain_tolerance_deg, 5);
  EXPECT_EQ(*batch.instance.items[1].grain_deg, 0);
  EXPECT_EQ(batch.instance.items[1].grain_tolerance_deg, 20);
  Bin plain = hide_with_backbone(0);
  plain.backbone_deg.reset();
  const BatchInstance free = hide_batch({{"J1", "", 0, items}}, {plain}, spec, "b");
  EXPECT_FALSE(free.instance.items[0].grain_deg);  // no backbone: the grain means nothing
  EXPECT_FALSE(free.instance.items[1].grain_deg);

  NestOptions options;
  options.time_limit_s = 1;
  const Layout layout = nest_batch(batch, options);
  ASSERT_EQ(layout.placements.size(), 3u);  // 2 vamps and the mold
  EXPECT_TRUE(check_layout(layout, batch.instance).empty());
  for (const Placement& p : layout.placements) {
    if (p.item != 0) continue;
    // The vamp's grain line (30 deg in its frame) after the placement's turn lies along the
    // backbone (90 deg), either way, within 5 deg.
    double off = std::fmod(std::abs(30 + p.rotation_deg - 90), 180.0);
    off = std::min(off, 180 - off);
    EXPECT_LE(off, 5 + 1e-6) << "rotation " << p.rotation_deg;
  }
}

}  // namespace
}  // namespace lastcut
