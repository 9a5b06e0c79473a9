// Reading a style drawn on the forme (engine/style/forme_drawing.hpp) from DXF files written here by
// hand, the way CAD programs write them: lines in pieces, out of order and reversed, arcs, polylines;
// layers naming a half; piece texts. Every refusal is checked word for word.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "engine/core/engine_error.hpp"
#include "engine/style/forme_drawing.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

// A minimal ASCII DXF file holding `entities` (group code / value pairs, one per line), $INSUNITS mm.
std::string dxf_file(const std::string& entities) {
  return "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n" + entities + "0\nENDSEC\n0\nEOF\n";
}

std::string line(const std::string& layer, double x1, double y1, double x2, double y2) {
  return "0\nLINE\n8\n" + layer + "\n10\n" + std::to_string(x1) + "\n20\n" + std::to_string(y1) + "\n11\n" + std::to_string(x2) +
         "\n21\n" + std::to_string(y2) + "\n";
}

std::string text(const std::string& layer, double x, double y, const std::string& words) {
  return "0\nTEXT\n8\n" + layer + "\n10\n" + std::to_string(x) + "\n20\n" + std::to_string(y) + "\n40\n5\n1\n" + words + "\n";
}

class FormeDrawingRead : public ::testing::Test {
 protected:
  fs::path write(const std::string& entities) {
    const fs::path file = dir_ / "forme.dxf";
    std::ofstream(file) << dxf_file(entities);
    return file;
  }
  std::string refusal(const std::string& entities) {
    try {
      read_forme_drawing(write(entities));
    } catch (const EngineError& error) {
      return error.what();
    }
    return "";
  }
  std::string file() const { return (dir_ / "forme.dxf").string(); }
  test::TempDir dir_{"forme-drawing"};
};

TEST_F(FormeDrawingRead, LinesInPiecesJoinEndToEnd) {
  // Three LINEs of one line, out of order and one reversed, then an ARC continuing it (a quarter circle
  // about (30, 10) from (30, 0) to (40, 10)); a one-half line; two piece texts.
  const FormeDrawing drawing = read_forme_drawing(write(
      line("LINE-vamp", 20, 0, 30, 0) + line("LINE-vamp", 10, 0, 0, 0) + line("LINE-vamp", 10, 0, 20, 0) +
      "0\nARC\n8\nLINE-vamp\n10\n30\n20\n10\n40\n10\n50\n270\n51\n360\n" + line("LINE-medial-eyestay", 5, 5, 5, 50) +
      text("PIECES", 12, 30, "vamp") + text("PIECES", 3, 20, "medial quarter")));
  ASSERT_EQ(drawing.lines.size(), 2u);
  const FormeLineDrawing& vamp = drawing.lines[0];
  EXPECT_EQ(vamp.name, "vamp");
  EXPECT_EQ(vamp.halves, FormeHalves::Both);
  EXPECT_EQ(vamp.points_mm.front(), Point2(0, 0));
  EXPECT_NEAR((vamp.points_mm.back() - Point2(40, 10)).norm(), 0, 1e-9);
  for (const Point2& p : vamp.points_mm)  // along the x axis, then on the arc
    EXPECT_TRUE(std::abs(p.y()) < 1e-9 || std::abs((p - Point2(30, 10)).norm() - 10) < 1e-9) << p.transpose();
  for (std::size_t i = 1; i < vamp.points_mm.size(); ++i) EXPECT_GT((vamp.points_mm[i] - vamp.points_mm[i - 1]).norm(), 0);
  EXPECT_EQ(drawing.lines[1].name, "eyestay");
  EXPECT_EQ(drawing.lines[1].halves, FormeHalves::Medial);
  ASSERT_EQ(drawing.pieces.size(), 2u);
  EXPECT_EQ(drawing.pieces[0].name, "vamp");
  EXPECT_EQ(drawing.pieces[0].half, FormeHalves::Lateral);
  EXPECT_EQ(drawing.pieces[0].at_mm, Point2(12, 30));
  EXPECT_EQ(drawing.pieces[1].half, FormeHalves::Medial);
}

TEST_F(FormeDrawingRead, ALineClosedOnItselfStaysClosed) {
  const FormeDrawing drawing = read_forme_drawing(write(line("LINE-cap", 0, 0, 10, 0) + line("LINE-cap", 10, 10, 10, 0) +
                                                        line("LINE-cap", 10, 10, 0, 0) + text("PIECES", 5, 2, "cap")));
  ASSERT_EQ(drawing.lines.size(), 1u);
  EXPECT_EQ(drawing.lines[0].points_mm.size(), 4u);
  EXPECT_EQ(drawing.lines[0].points_mm.front(), drawing.lines[0].points_mm.back());
}

TEST_F(FormeDrawingRead, UnreadableDrawingsAreRefusedInOneLine) {
  const std::string piece = text("PIECES", 1, 1, "vamp");
  EXPECT_EQ(refusal(line("LINE-vamp", 0, 0, 10, 0) + line("LINE-vamp", 20, 0, 30, 0) + piece),
            file() + ": line vamp (layer LINE-vamp) is in 2 parts that do not join: one ends at (10.0, 0.0); join them end to end");
  EXPECT_EQ(refusal(line("LINE-vamp", 0, 0, 10, 0) + line("LINE-vamp", 10, 0, 20, 0) + line("LINE-vamp", 10, 0, 10, 10) + piece),
            file() + ": line vamp (layer LINE-vamp) branches at (10.0, 0.0): a line is one stroke, end to end");
  EXPECT_EQ(refusal("0\nSPLINE\n8\nLINE-vamp\n10\n0\n20\n0\n" + piece),
            file() + ": line on layer LINE-vamp has a SPLINE, which lastcut does not read: draw it with lines, polylines or arcs "
                     "(explode or convert it)");
  EXPECT_EQ(refusal(line("LINE-vamp line", 0, 0, 10, 0) + piece),
            file() + ": layer \"LINE-vamp line\": a line's name holds letters, digits, - and _ only (an R12 layer name)");
  EXPECT_EQ(refusal(line("LINE-medial-", 0, 0, 10, 0) + piece),
            file() + ": layer LINE-medial- names no line: call it LINE-<name>, LINE-medial-<name> or LINE-lateral-<name>");
  EXPECT_EQ(refusal(line("LINE-vamp", 0, 0, 10, 0) + line("LINE-medial-vamp", 0, 5, 10, 5) + piece),
            file() + ": line vamp is drawn on layers LINE-vamp and LINE-medial-vamp: draw it once for both halves (LINE-name) or "
                     "once per half (LINE-medial-, LINE-lateral-)");
  EXPECT_EQ(refusal(line("LINE-vamp", 0, 0, 0, 0) + piece), file() + ": line vamp (layer LINE-vamp) has no length");
  EXPECT_EQ(refusal(line("LINE-vamp", 0, 0, 10, 0) + text("PIECES", 4, 5, "  ")),
            file() + ": an empty text on layer PIECES at (4.0, 5.0)");
  EXPECT_EQ(refusal(line("LINE-vamp", 0, 0, 10, 0)),
            file() + ": no piece text: write each piece's name as a TEXT on layer PIECES, inside the piece");
}

}  // namespace
}  // namespace lastcut
