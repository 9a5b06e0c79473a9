// The independent reading of G-code cut files the piece tests judge by (gcode_pieces.hpp,
// piece_orders.hpp): labels, the knife's path with its arcs, the principal axis, and the checks
// failing where they must: a piece on a zone below its grade, a grain off the backbone, a piece cut
// that no job has.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/daemon/gcode_pieces.hpp"
#include "tests/daemon/piece_orders.hpp"

namespace lastcut::daemon::testing {
namespace {

// A 100 x 40 mm rectangle turned by `turn_deg` about (x, y), cut with the knife down (Z -1.8) and
// 1.5 mm of overcut, after a pen stroke (M8/M9) that must not count.
std::string rectangle_gcode(const std::string& label, double x, double y, double turn_deg) {
  const double c = std::cos(turn_deg * std::numbers::pi / 180), s = std::sin(turn_deg * std::numbers::pi / 180);
  auto at = [&](double u, double v) {
    char text[64];
    std::snprintf(text, sizeof text, "X%.3f Y%.3f", x + c * u - s * v, y + s * u + c * v);
    return std::string(text);
  };
  return "G0 Z3\n; piece 1/1: " + label + " (item 4)\nG0 " + at(10, 10) + "\nM8\nG1 " + at(30, 10) + " F3600\nM9\n" +
         "G0 " + at(0, 0) + "\nG1 Z-1.8 F600\nG1 " + at(100, 0) + " F2400\nG1 " + at(100, 40) + "\nG1 " + at(0, 40) + "\nG1 " +
         at(0, 0) + "\nG1 " + at(1.5, 0) + "\nG0 Z3\n";
}

NestItem rectangle_item(const std::string& label, int min_quality, double grain_deg) {
  NestItem item;
  item.label = label;
  item.shape.points = {{0, 0}, {100, 0}, {100, 40}, {0, 40}};
  item.min_quality = min_quality;
  item.grain_deg = grain_deg;
  item.grain_tolerance_deg = 10;
  return item;
}

TEST(GcodePieces, LabelsPathsAndArcs) {
  const std::vector<CutPiece> pieces = pieces_of_gcode(rectangle_gcode("#7 42 R vamp", 200, 100, 30));
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].label, "#7 42 R vamp");
  EXPECT_EQ(pieces[0].item, 4);
  const Polygon2 outline = cut_outline(pieces[0]);
  EXPECT_NEAR(std::abs(signed_area(outline)), 4000, 0.05);  // the pen stroke and the overcut left out (0.001 mm digits)
  EXPECT_NEAR(principal_axis_deg(outline), 30, 1e-3);
  // A half circle of radius 50 as a G3 arc, closed by its diameter.
  const std::vector<CutPiece> arc = pieces_of_gcode("; piece 1/1: disc (item 0)\nG0 X50 Y0\nG1 Z-1\nG3 X-50 Y0 I-50 J0\nG1 X50 Y0\nG1 X50.5 Y0\n");
  ASSERT_EQ(arc.size(), 1u);
  EXPECT_NEAR(std::abs(signed_area(cut_outline(arc[0]))), std::numbers::pi * 2500 / 2, 3);
}

TEST(GcodePieces, ChecksFailWhereTheyMust) {
  const std::vector<QualityZone> zones = {{Polygon2{{{0, 0}, {150, 0}, {150, 150}, {0, 150}}}, 1}};
  const std::map<std::string, NestItem> items = {{"vamp", rectangle_item("vamp", 3, 0)}, {"lining", rectangle_item("lining", 0, 90)}};
  CutPieces good;
  check_cut_file(rectangle_gcode("vamp", 300, 300, 5), "b1", zones, items, good);
  EXPECT_TRUE(good.problems.empty()) << good.problems.front();
  EXPECT_EQ(good.zone_checks, 1);
  EXPECT_EQ(good.grain_checks, 1);
  EXPECT_EQ(good.times_cut["vamp"], 1);
  EXPECT_EQ(good.hide_of["vamp"], "b1");

  CutPieces bad;
  check_cut_file(rectangle_gcode("vamp", 100, 100, 0), "b2", zones, items, bad);   // on the zone
  check_cut_file(rectangle_gcode("vamp", 300, 300, 25), "b2", zones, items, bad);  // 25 deg off
  check_cut_file(rectangle_gcode("strap", 300, 300, 0), "b2", zones, items, bad);  // no job has it
  ASSERT_EQ(bad.problems.size(), 3u);
  EXPECT_NE(bad.problems[0].find("lies"), std::string::npos) << bad.problems[0];
  EXPECT_NE(bad.problems[1].find("deg off the backbone"), std::string::npos) << bad.problems[1];
  EXPECT_NE(bad.problems[2].find("a piece no job has"), std::string::npos) << bad.problems[2];
}

}  // namespace
}  // namespace lastcut::daemon::testing
