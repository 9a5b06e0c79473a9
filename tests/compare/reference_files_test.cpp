// Reading reference patterns: DXF (LWPOLYLINE, POLYLINE, bulges, $INSUNITS) and SVG paths
// (units, relative commands, curves), and the one-line refusals of bad files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "engine/compare/reference_outline.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/mold/mold_dxf.hpp"
#include "tests/compare/synthetic_mold.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

class ReferenceFiles : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = lastcut::test::make_temp_dir("reference-files");
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  static void expect_refusal(const fs::path& file, const std::string& expected_after_name) {
    try {
      read_reference_outline(file);
      ADD_FAILURE() << file << " was read";
    } catch (const EngineError& error) {
      EXPECT_EQ(std::string(error.what()), file.string() + expected_after_name);
    }
  }
  static inline fs::path dir_;
};

double area_of(const Polygon2& p) {
  double twice = 0.0;
  for (size_t i = 0; i < p.points.size(); ++i) {
    const Point2& a = p.points[i];
    const Point2& b = p.points[(i + 1) % p.points.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

std::string dxf(const std::string& header, const std::string& entities) {
  return "0\nSECTION\n2\nHEADER\n" + header + "0\nENDSEC\n0\nSECTION\n2\nENTITIES\n" + entities + "0\nENDSEC\n0\nEOF\n";
}

std::string lwpolyline(const std::vector<Point2>& points, bool closed, const std::string& bulges = "") {
  std::string text = "0\nLWPOLYLINE\n8\nOUTLINE\n90\n" + std::to_string(points.size()) + "\n70\n" + (closed ? "1" : "0") + "\n";
  for (size_t i = 0; i < points.size(); ++i) {
    text += "10\n" + std::to_string(points[i].x()) + "\n20\n" + std::to_string(points[i].y()) + "\n";
    if (!bulges.empty()) text += "42\n" + bulges + "\n";
  }
  return text;
}

TEST_F(ReferenceFiles, DxfInCentimetresLargestClosedOutlineWins) {
  const auto file = write("cm.dxf", dxf("9\n$INSUNITS\n70\n5\n",
                                         lwpolyline({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, true) +
                                             lwpolyline({{0, 0}, {10, 0}, {10, 5}, {0, 5}}, true) +
                                             lwpolyline({{0, 0}, {50, 0}, {50, 50}}, false)));
  const Mold mold = read_reference_outline(file);
  EXPECT_DOUBLE_EQ(area_of(mold.outline), 100.0 * 50.0);  // 10 x 5 cm, counter-clockwise
  EXPECT_EQ(mold.name, "cm");
  EXPECT_TRUE(mold.marks.empty());
}

TEST_F(ReferenceFiles, DxfBulgeCircleWithinTolerance) {
  // Two half-circle arcs (bulge 1) of radius 10 mm, $INSUNITS absent: mm.
  const auto file = write("circle.dxf", dxf("", lwpolyline({{-10, 0}, {10, 0}}, true, "1.0")));
  const Mold mold = read_reference_outline(file);
  ASSERT_GT(mold.outline.points.size(), 20u);
  double worst_sagitta = 0.0;
  for (size_t i = 0; i < mold.outline.points.size(); ++i) {
    const Point2& a = mold.outline.points[i];
    const Point2& b = mold.outline.points[(i + 1) % mold.outline.points.size()];
    EXPECT_NEAR(a.norm(), 10.0, 1e-9);
    worst_sagitta = std::max(worst_sagitta, 10.0 - (0.5 * (a + b)).norm());
  }
  EXPECT_LE(worst_sagitta, kCurveTolerance_mm);
  EXPECT_GT(worst_sagitta, 0.25 * kCurveTolerance_mm);  // not needlessly fine either
  EXPECT_NEAR(area_of(mold.outline), std::numbers::pi * 100.0, 2.0 * std::numbers::pi * 10.0 * kCurveTolerance_mm);
}

TEST_F(ReferenceFiles, DxfR12PolylineInInches) {
  std::string entities = "0\nPOLYLINE\n8\n0\n66\n1\n10\n0\n20\n0\n70\n1\n";
  for (const Point2& p : {Point2(0, 0), Point2(2, 0), Point2(2, 1), Point2(0, 1)})
    entities += "0\nVERTEX\n8\n0\n10\n" + std::to_string(p.x()) + "\n20\n" + std::to_string(p.y()) + "\n";
  entities += "0\nSEQEND\n";
  const Mold mold = read_reference_outline(write("inch.DXF", dxf("9\n$INSUNITS\n70\n1\n", entities)));
  EXPECT_NEAR(area_of(mold.outline), 2.0 * 25.4 * 25.4, 1e-9);
}

TEST_F(ReferenceFiles, LastcutMoldKeepsItsMarks) {
  const Mold original = testing::synthetic_mold();
  write_mold_dxf(dir_ / "mold.dxf", original);
  const Mold mold = read_reference_outline(dir_ / "mold.dxf");
  ASSERT_EQ(mold.marks.size(), 4u);
  EXPECT_EQ(mold.marks[1].name, "toe");
  EXPECT_LT((mold.marks[1].position_mm - original.marks[1].position_mm).norm(), 1e-6);
  EXPECT_NEAR(area_of(mold.outline), area_of(original.outline), 1e-3);
}

TEST_F(ReferenceFiles, SvgUnitsRelativeCommandsAndCurves) {
  // viewBox 100 wide drawn 200 mm wide: 2 mm per user unit; y flips, handedness is kept.
  const auto box = write("box.svg",
                         "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200mm\" "
                         "height=\"100mm\" viewBox=\"0 0 100 50\">\n<path d=\"M10,10 h30 v20 h-30 z\"/>\n"
                         "<path d='M0 0 L1 0 L1 1'/></svg>\n");
  const Polygon2 outline = read_reference_outline(box).outline;
  EXPECT_NEAR(area_of(outline), 60.0 * 40.0, 1e-9);
  // The corner (10, 10) of the drawing, y flipped, made counter-clockwise.
  EXPECT_EQ(std::count(outline.points.begin(), outline.points.end(), Point2(20.0, -20.0)), 1);
  EXPECT_GT(area_of(outline), 0.0);
  // No viewBox: user units are CSS pixels, 96 per inch. A quadratic segment over a chord: 2/3 of
  // the control triangle (Archimedes).
  const auto quadratic = write("quadratic.svg", "<svg width=\"100\" height=\"100\"><path d=\"M0 100 Q 50 -100 100 100 Z\"/></svg>");
  const double px = 25.4 / 96.0;
  const double parabola_mm2 = 2.0 / 3.0 * (0.5 * 100.0 * 200.0) * px * px;
  const Polygon2 q = read_reference_outline(quadratic).outline;
  EXPECT_LE(area_of(q), parabola_mm2 + 1e-9);
  EXPECT_GT(area_of(q), parabola_mm2 - perimeter(q) * kCurveTolerance_mm);
  // A cubic with P0 (0,0), P1 (0,h), P2 (w,h), P3 (w,0) closes 3/5 w h (integral of y dx);
  // written relative after a relative move.
  const auto cubic = write("cubic.svg", "<svg viewBox=\"0 0 10 10\" width=\"10mm\"><path d=\"m 5 5 c 0,-100 100,-100 100,0 z\"/></svg>");
  const Polygon2 c = read_reference_outline(cubic).outline;
  EXPECT_LE(area_of(c), 0.6 * 100.0 * 100.0 + 1e-9);
  EXPECT_GT(area_of(c), 0.6 * 100.0 * 100.0 - perimeter(c) * kCurveTolerance_mm);
}

TEST_F(ReferenceFiles, BadFilesAreRefusedWithOneLine) {
  expect_refusal(write("notes.txt", "heel 3 mm\n"), ": not a pattern file; expected a .dxf or .svg outline");
  expect_refusal(write("empty.dxf", ""), ": the file is empty");
  expect_refusal(write("empty.svg", ""), ": the file is empty");
  expect_refusal(write("open.dxf", dxf("", lwpolyline({{0, 0}, {50, 0}, {50, 50}}, false))),
                 ": no closed outline (1 open, close the outline in the drawing program)");
  expect_refusal(write("feet.dxf", dxf("9\n$INSUNITS\n70\n2\n", lwpolyline({{0, 0}, {1, 0}, {1, 1}}, true))),
                 ": drawing units $INSUNITS 2 are not supported; save the pattern in mm, cm, m or inches");
  expect_refusal(write("huge.dxf", dxf("9\n$INSUNITS\n70\n6\n", lwpolyline({{0, 0}, {2e3, 0}, {2e3, 2e3}}, true))),
                 ": coordinates beyond 1 km; check the drawing's units");
  expect_refusal(write("text.dxf", "this is not\na drawing\n"), " is not a DXF file: line 1 is not a group code");
  // Sizes no shoe pattern has (wrong units, or a drawing that would keep the comparison busy for minutes).
  expect_refusal(write("metres.dxf", dxf("9\n$INSUNITS\n70\n6\n", lwpolyline({{0, 0}, {0.27, 0}, {0.27, 3.1}}, true))),
                 ": the outline is 270 x 3100 mm, larger than a shoe pattern; check the drawing's units");
  expect_refusal(write("unitless.dxf", dxf("", lwpolyline({{0, 0}, {0.27, 0}, {0.27, 0.1}}, true))),
                 ": the outline is 0.27 x 0.1 mm, smaller than a shoe pattern; check the drawing's units");
  std::vector<Point2> serpentine;  // 1900 x 70 mm, six runs across: 11.5 m around
  for (int run = 0; run < 6; ++run) {
    const double y = 12.0 * run, from = run % 2 == 0 ? 10.0 : 1900.0, to = run % 2 == 0 ? 1900.0 : 10.0;
    serpentine.push_back({from, y});
    serpentine.push_back({to, y});
  }
  serpentine.push_back({0, 60});
  serpentine.push_back({0, 0});
  expect_refusal(write("serpentine.dxf", dxf("", lwpolyline(serpentine, true))),
                 ": the outline is 11.5 m long, longer than 10 m; it is no shoe pattern");
  expect_refusal(write("far-curve.svg", "<svg width=\"270mm\" viewBox=\"0 0 270 120\"><path d=\"M 0 100 C 60 140 200 120 "
                                        "2E62 88 L 28 -4 Z\"/></svg>"),
                 ": coordinates beyond 1 km; check the drawing's units");
  std::string dense = "<svg width=\"300mm\" viewBox=\"0 0 300 300\"><path d=\"M0 0";
  for (int k = 1; k <= 20000; ++k) dense += " L" + std::to_string(0.015 * k) + " " + std::to_string((k % 2) * 0.01);
  dense += " L 300 200 Z\"/></svg>";
  expect_refusal(write("dense.svg", dense), ": an outline of 20002 points, more than 20000; simplify it in the drawing program");
  // A traced outline that crosses itself (a figure eight): no one area to compare. A repeated point is no crossing.
  expect_refusal(write("crossed.dxf", dxf("", lwpolyline({{0, 0}, {100, 60}, {100, 0}, {0, 40}}, true))),
                 ": the outline crosses or touches itself near (40.0, 24.0) mm; a pattern is one line that does not "
                 "cross itself, fix it in the drawing program");
  EXPECT_NO_THROW(read_reference_outline(
      write("repeated-point.dxf", dxf("", lwpolyline({{0, 0}, {100, 0}, {100, 0}, {100, 50}, {0, 50}, {0, 0}}, true)))));
  expect_refusal(write("nothing.dxf", dxf("", "")), ": no closed outline");
  expect_refusal(write("arc.svg", "<svg width=\"10mm\" viewBox=\"0 0 10 10\"><path d=\"M0 0 A 5 5 0 0 1 10 0 Z\"/></svg>"),
                 ": path command 'A' is not supported; use M, L, H, V, C, Q and Z (convert arcs and smooth curves to paths)");
  expect_refusal(write("open.svg", "<svg width=\"10mm\" viewBox=\"0 0 10 10\"><path d=\"M0 0 L 5 0 L 5 5\"/></svg>"),
                 ": no closed outline (1 open, close the outline in the drawing program)");
  expect_refusal(write("html.svg", "<html><body>pattern</body></html>"), " is not an SVG file: no <svg> element");
  expect_refusal(write("moved.svg", "<svg width=\"10mm\" viewBox=\"0 0 10 10\"><g transform=\"translate(5 5)\">"
                                    "<path d=\"M0 0 H 5 V 5 Z\"/></g></svg>"),
                 ": transform attributes are not supported; apply them to the paths first");
  expect_refusal(write("percent.svg", "<svg width=\"100%\" viewBox=\"0 0 10 10\"><path d=\"M0 0 H 5 V 5 Z\"/></svg>"),
                 ": the drawing size (width \"100%\", viewBox \"0 0 10 10\") gives no scale in mm");
  try {
    read_reference_outline(dir_ / "missing.svg");
    ADD_FAILURE() << "a missing file was read";
  } catch (const EngineError& error) {
    EXPECT_EQ(std::string(error.what()), "cannot read pattern file " + (dir_ / "missing.svg").string());
  }
}

}  // namespace
}  // namespace lastcut
