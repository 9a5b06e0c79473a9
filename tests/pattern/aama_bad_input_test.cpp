// Every class of bad DXF-AAMA input is refused with an EngineError of one exact line naming the
// file; and the writer refuses pieces it cannot write truthfully. Files are written by hand
// (aama_test_files.hpp), nothing is mocked.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "aama_test_files.hpp"
#include "engine/pattern/aama_dxf.hpp"
#include "tests/support/engine_refusal.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut::test {
namespace {

// The refusal's message, checked to be one line.
template <typename Action>
std::string refusal(Action action) {
  const std::string message = engine_refusal(action);
  EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
  return message;
}

std::string read_refusal(const std::string& text) {
  return refusal([&] { read_aama_dxf_text(text, "bad.dxf"); });
}

void closed_square(HandDxf& dxf) { dxf.polyline("1", square(100.0), true); }

TEST(AamaDxfBadInput, MissingAndEmptyFiles) {
  TempDir dir("aama-missing");
  EXPECT_EQ(refusal([&] { read_aama_dxf(dir / "nope.dxf"); }), "cannot read pattern file " + (dir / "nope.dxf").string());
  std::ofstream(dir / "empty.dxf").close();
  EXPECT_EQ(refusal([&] { read_aama_dxf(dir / "empty.dxf"); }), (dir / "empty.dxf").string() + ": the file is empty");
}

TEST(AamaDxfBadInput, NotADxfFile) {
  EXPECT_EQ(read_refusal("Piece Name: vamp\nQuantity: 2\n"), "bad.dxf is not a DXF file: line 1 is not a group code");
  EXPECT_EQ(read_refusal("0\nHELLO\n999\nworld\n"), "bad.dxf is not a DXF file: it has no SECTION");
  EXPECT_EQ(read_refusal("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n"), "bad.dxf is not a DXF file: it ends in the middle of a group at line 7");
}

TEST(AamaDxfBadInput, NoPieceBlocks) {
  // A plain DXF outline in ENTITIES: a drawing, but no AAMA piece.
  HandDxf dxf;
  dxf.header(4).section("ENTITIES").polyline("1", square(100.0), true).end_section().eof();
  EXPECT_EQ(read_refusal(dxf.str()), "bad.dxf: no piece blocks (DXF-AAMA places each piece as a BLOCK with an INSERT)");
  // A block defined but never placed is no piece either.
  HandDxf unplaced;
  unplaced.header(4).section("BLOCKS").block("vamp").polyline("1", square(100.0), true).end_block().end_section().eof();
  EXPECT_EQ(read_refusal(unplaced.str()), "bad.dxf: no piece blocks (DXF-AAMA places each piece as a BLOCK with an INSERT)");
}

TEST(AamaDxfBadInput, InsertOfAnUndefinedBlock) {
  HandDxf dxf;
  dxf.header(4).section("ENTITIES").insert("heel", Point2(0, 0)).end_section().eof();
  EXPECT_EQ(read_refusal(dxf.str()), "bad.dxf: an INSERT places block \"heel\", which the BLOCKS section does not define");
}

TEST(AamaDxfBadInput, CutLineOpenMissingOrTwice) {
  EXPECT_EQ(read_refusal(one_piece_file(4, [](HandDxf& d) { d.polyline("1", square(100.0), false); })),
            "bad.dxf: piece \"vamp\": its cut line on layer 1 is open");
  EXPECT_EQ(read_refusal(one_piece_file(4, [](HandDxf& d) { d.lwpolyline("1", square(100.0), false); })),
            "bad.dxf: piece \"vamp\": its cut line on layer 1 is open");
  // Outlines on other layers are not cut lines.
  EXPECT_EQ(read_refusal(one_piece_file(4, [](HandDxf& d) { d.polyline("8", square(100.0), true); })),
            "bad.dxf: piece \"vamp\": no cut line on layer 1");
  EXPECT_EQ(read_refusal(one_piece_file(4, [](HandDxf& d) { closed_square(d); closed_square(d); })),
            "bad.dxf: piece \"vamp\": 2 cut lines on layer 1; a piece has one");
  EXPECT_EQ(read_refusal(one_piece_file(4, [](HandDxf& d) { d.polyline("1", {{0, 0}, {1, 0}}, true); })),
            "bad.dxf: piece \"vamp\": its cut line on layer 1 has fewer than 3 points");
}

TEST(AamaDxfBadInput, UnknownOrContradictoryUnits) {
  EXPECT_EQ(read_refusal(one_piece_file(0, [](HandDxf& d) { closed_square(d); d.text("1", "Units: FURLONG"); })),
            "bad.dxf: unknown units \"Units: FURLONG\" (METRIC, MM, CM, ENGLISH or INCH)");
  EXPECT_EQ(read_refusal(one_piece_file(2, closed_square)),
            "bad.dxf: drawing units $INSUNITS 2 are not supported; save the pattern in mm, cm, m or inches");
  EXPECT_EQ(read_refusal(one_piece_file(4, [](HandDxf& d) { closed_square(d); d.text("1", "Units: ENGLISH"); })),
            "bad.dxf: the units text \"Units: ENGLISH\" and $INSUNITS 4 disagree");
  // Unitless with the text: the text decides (inches here).
  const auto pieces = read_aama_dxf_text(one_piece_file(0, [](HandDxf& d) { closed_square(d); d.text("1", "Units: INCH"); }), "ok.dxf");
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_NEAR(pieces[0].cut_line_mm[2].x(), 2540.0, 1e-9);
}

TEST(AamaDxfBadInput, QuantityThatIsNotAPositiveCount) {
  for (const std::string quantity : {"two", "0", "-3", "2.5", "99999999999"}) {
    EXPECT_EQ(read_refusal(one_piece_file(4, [&](HandDxf& d) { closed_square(d); d.text("1", "Quantity: " + quantity); })),
              "bad.dxf: piece \"vamp\": quantity '" + quantity + "' is not a positive count");
  }
}

TEST(AamaDxfBadInput, WriterRefusesWhatItCannotWriteTruthfully) {
  PatternPiece piece = sample_piece("vamp", "42", Point2(0, 0), 100.0, 60.0);
  EXPECT_EQ(refusal([] { aama_dxf_text({}); }), "DXF-AAMA: no pieces to write");
  PatternPiece clockwise = piece;
  std::reverse(clockwise.cut_line_mm.begin(), clockwise.cut_line_mm.end());
  EXPECT_EQ(refusal([&] { aama_dxf_text({clockwise}); }),
            "DXF-AAMA: piece \"vamp\": its cut line is clockwise or has no area; cut lines are counter-clockwise");
  PatternPiece umlaut = piece;
  umlaut.category = "Rindsleder f\xc3\xbcr Schaft";
  EXPECT_EQ(refusal([&] { aama_dxf_text({umlaut}); }),
            "DXF-AAMA: piece \"vamp\": the category has a character outside printable ASCII (DXF-AAMA text is 7-bit ASCII)");
  // A line break would end the DXF value and let the rest pass for groups of its own.
  PatternPiece forged = piece;
  forged.annotation = "right\n0\nLINE";
  EXPECT_EQ(refusal([&] { aama_dxf_text({forged}); }),
            "DXF-AAMA: piece \"vamp\": the annotation has a character outside printable ASCII (DXF-AAMA text is 7-bit ASCII)");
  PatternPiece none = piece;
  none.quantity = 0;
  EXPECT_EQ(refusal([&] { aama_dxf_text({none}); }), "DXF-AAMA: piece \"vamp\": quantity 0 is not a positive count");
  PatternPiece unnamed = piece;
  unnamed.name.clear();
  EXPECT_EQ(refusal([&] { aama_dxf_text({unnamed}); }), "DXF-AAMA: a piece without a name");
  PatternPiece no_direction = piece;
  no_direction.notches[1].inward = Point2::Zero();
  EXPECT_EQ(refusal([&] { aama_dxf_text({no_direction}); }), "DXF-AAMA: piece \"vamp\": a notch has no inward direction");
  // write_aama_dxf names the file, and leaves none behind.
  TempDir dir("aama-write-refusal");
  EXPECT_EQ(refusal([&] { write_aama_dxf(dir / "out.dxf", {none}); }),
            (dir / "out.dxf").string() + ": DXF-AAMA: piece \"vamp\": quantity 0 is not a positive count");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.dxf"));
}

}  // namespace
}  // namespace lastcut::test
