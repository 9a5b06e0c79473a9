// DXF-AAMA round trip: pieces written by write_aama_dxf read back the same by read_aama_dxf (within
// 1e-6 mm), the layout keeps them apart, and files as other pattern CAD writes them (LWPOLYLINE
// with bulges, clockwise, notch LINEs, inches, a block placed twice) read as they should.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "aama_test_files.hpp"
#include "engine/core/dxf_reader.hpp"
#include "engine/pattern/aama_dxf.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut::test {
namespace {

void expect_near_points(const std::vector<Point2>& actual, const std::vector<Point2>& expected, const std::string& what) {
  ASSERT_EQ(actual.size(), expected.size()) << what;
  for (size_t i = 0; i < actual.size(); ++i) EXPECT_LT((actual[i] - expected[i]).norm(), 1e-6) << what << " point " << i;
}

void expect_same_piece(const PatternPiece& actual, const PatternPiece& expected) {
  SCOPED_TRACE(expected.name + " " + expected.size);
  EXPECT_EQ(actual.name, expected.name);
  EXPECT_EQ(actual.style, expected.style);
  EXPECT_EQ(actual.size, expected.size);
  EXPECT_EQ(actual.category, expected.category);
  EXPECT_EQ(actual.annotation, expected.annotation);
  EXPECT_EQ(actual.quantity, expected.quantity);
  expect_near_points(actual.cut_line_mm, expected.cut_line_mm, "cut line");
  ASSERT_EQ(actual.internal_lines_mm.size(), expected.internal_lines_mm.size());
  for (size_t i = 0; i < actual.internal_lines_mm.size(); ++i)
    expect_near_points(actual.internal_lines_mm[i], expected.internal_lines_mm[i], "internal line");
  ASSERT_EQ(actual.sew_lines_mm.size(), expected.sew_lines_mm.size());
  for (size_t i = 0; i < actual.sew_lines_mm.size(); ++i)
    expect_near_points(actual.sew_lines_mm[i], expected.sew_lines_mm[i], "sew line");
  ASSERT_EQ(actual.notches.size(), expected.notches.size());
  for (size_t i = 0; i < actual.notches.size(); ++i) {
    EXPECT_LT((actual.notches[i].at_mm - expected.notches[i].at_mm).norm(), 1e-6) << "notch " << i;
    EXPECT_LT((actual.notches[i].inward - expected.notches[i].inward).norm(), 1e-6) << "notch " << i;
  }
  ASSERT_EQ(actual.grain_line_mm.has_value(), expected.grain_line_mm.has_value());
  if (expected.grain_line_mm) {
    EXPECT_LT(((*actual.grain_line_mm)[0] - (*expected.grain_line_mm)[0]).norm(), 1e-6);
    EXPECT_LT(((*actual.grain_line_mm)[1] - (*expected.grain_line_mm)[1]).norm(), 1e-6);
  }
}

std::vector<PatternPiece> sample_pieces() {
  PatternPiece vamp = sample_piece("vamp", "42", Point2(130.25, 40.5), 120.0, 80.0);
  PatternPiece quarter = sample_piece("quarter", "42", Point2(-300.0, 7.123456), 90.0, 45.0);
  quarter.quantity = 4;
  quarter.annotation = "left";
  quarter.grain_line_mm.reset();
  quarter.sew_lines_mm.clear();
  // The same name again (another size): a second block of its own.
  PatternPiece vamp_43 = sample_piece("vamp", "43", Point2(0.0, 0.0), 125.0, 83.0);
  vamp_43.category = "";
  vamp_43.quantity = 1;
  return {vamp, quarter, vamp_43};
}

TEST(AamaDxf, RoundTripGivesTheSamePieces) {
  TempDir dir("aama-round-trip");
  const std::vector<PatternPiece> pieces = sample_pieces();
  write_aama_dxf(dir / "derby.dxf", pieces);
  const std::vector<PatternPiece> read = read_aama_dxf(dir / "derby.dxf");
  ASSERT_EQ(read.size(), pieces.size());
  for (size_t i = 0; i < pieces.size(); ++i) expect_same_piece(read[i], pieces[i]);
}

TEST(AamaDxf, FileIsR12InMillimetresWithOneInsertedBlockPerPiece) {
  const std::vector<PatternPiece> pieces = sample_pieces();
  const std::string text = aama_dxf_text(pieces);
  EXPECT_NE(text.find("$ACADVER\n1\nAC1009\n"), std::string::npos);
  EXPECT_NE(text.find("$INSUNITS\n70\n4\n"), std::string::npos);
  const DxfDrawing drawing = read_dxf_drawing_text(text, "derby.dxf");
  ASSERT_EQ(drawing.blocks.size(), 3u);
  ASSERT_EQ(drawing.inserts.size(), 3u);
  EXPECT_EQ(drawing.blocks[0].name, "vamp");
  EXPECT_EQ(drawing.blocks[1].name, "quarter");
  EXPECT_EQ(drawing.blocks[2].name, "vamp_2");
  ASSERT_EQ(drawing.texts.size(), 1u);
  EXPECT_EQ(drawing.texts[0].text, "Units: METRIC");
  EXPECT_EQ(drawing.texts[0].layer, "1");
  // Side by side: each placed cut line lies right of the previous one, none overlapping.
  double previous_right = -1e300;
  for (size_t i = 0; i < pieces.size(); ++i) {
    EXPECT_EQ(drawing.inserts[i].block, drawing.blocks[i].name);
    double left = 1e300, right = -1e300, bottom = 1e300;
    for (const Point2& p : pieces[i].cut_line_mm) {
      left = std::min(left, p.x() + drawing.inserts[i].at.x());
      right = std::max(right, p.x() + drawing.inserts[i].at.x());
      bottom = std::min(bottom, p.y() + drawing.inserts[i].at.y());
    }
    EXPECT_GT(left, previous_right + 10.0) << "piece " << i;
    EXPECT_GE(bottom, -1e-9) << "piece " << i;
    previous_right = right;
  }
}

// What another pattern system may write: an R14-style LWPOLYLINE cut line, clockwise, with a bulge
// (a round toe), in inches said by the "Units: ENGLISH" text, a notch drawn as a LINE from the
// outline inward, a notch POINT without an angle, a block placed twice, a style system text.
TEST(AamaDxf, ReadsOtherCadConventions) {
  HandDxf dxf;
  dxf.header(1).section("BLOCKS").block("TONGUE");
  dxf.text("1", "Piece Name: tongue").text("1", "quantity:3").text("1", "Size: 9");
  // Clockwise square of 2 inches, its top edge an arc bulging up (bulge 1: a half circle).
  dxf.lwpolyline("1", {{0, 0}, {0, 2}, {2, 2}, {2, 0}}, true, {0.0, -1.0, 0.0, 0.0});
  dxf.line("4", Point2(1, 0.25), Point2(1, 0));  // written inward end first: the reader orders it
  dxf.pair(0, "POINT").pair(8, "4").pair(10, 0.0).pair(20, 1.0);
  dxf.line("7", Point2(1, 0.5), Point2(1, 2.5)).line("7", Point2(1, 2.5), Point2(0.9, 2.4));  // arrow head
  dxf.end_block().end_section();
  dxf.section("ENTITIES").text("1", "Style Name: oxford").text("1", "Units: ENGLISH");
  dxf.insert("TONGUE", Point2(0, 0)).insert("TONGUE", Point2(5, 0)).end_section().eof();

  const std::vector<PatternPiece> pieces = read_aama_dxf_text(dxf.str(), "other.dxf");
  ASSERT_EQ(pieces.size(), 1u);
  const PatternPiece& tongue = pieces[0];
  EXPECT_EQ(tongue.name, "tongue");
  EXPECT_EQ(tongue.quantity, 3);
  EXPECT_EQ(tongue.size, "9");
  EXPECT_EQ(tongue.style, "oxford");
  // Counter-clockwise, in mm, the arc flattened: the highest point is the arc's top, 1 inch above
  // the chord at y = 2 inches.
  Polygon2 cut{tongue.cut_line_mm};
  EXPECT_GT(signed_area(cut), 0.0);
  double top = -1e300;
  for (const Point2& p : tongue.cut_line_mm) top = std::max(top, p.y());
  EXPECT_NEAR(top, 3.0 * 25.4, 0.05);
  EXPECT_GT(tongue.cut_line_mm.size(), 10u);
  // The square's area plus the half disc of radius 1 inch, within the flattening tolerance.
  EXPECT_NEAR(signed_area(cut), (4.0 + M_PI / 2.0) * 25.4 * 25.4, 10.0);
  ASSERT_EQ(tongue.notches.size(), 2u);
  // The POINT (listed first) on the left edge: inward is +x. The LINE on the bottom edge: +y.
  EXPECT_LT((tongue.notches[0].at_mm - Point2(0, 25.4)).norm(), 1e-9);
  EXPECT_LT((tongue.notches[0].inward - Point2(1, 0)).norm(), 1e-9);
  EXPECT_LT((tongue.notches[1].at_mm - Point2(25.4, 0)).norm(), 1e-9);
  EXPECT_LT((tongue.notches[1].inward - Point2(0, 1)).norm(), 1e-9);
  ASSERT_TRUE(tongue.grain_line_mm.has_value());
  EXPECT_LT(((*tongue.grain_line_mm)[1] - Point2(25.4, 2.5 * 25.4)).norm(), 1e-9);
}

}  // namespace
}  // namespace lastcut::test
