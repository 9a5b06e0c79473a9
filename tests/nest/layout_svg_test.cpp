// The cutting-room picture: labels fit their pieces, pieces left over are named, drawn lines dashed.
#include <gtest/gtest.h>

#include "engine/nest/layout_svg.hpp"
#include "tests/nest/nest_test_instances.hpp"

namespace lastcut {
namespace {

TEST(LayoutSvg, LongLabelsBreakIntoTwoLinesOnNarrowPiecesAndLeftoversAreNamed) {
  NestInstance instance;
  instance.name = "labels";
  instance.strip_height = 200;
  instance.items.push_back(test::item(0, test::rectangle(30, 150), 1, {0}));
  instance.items.back().label = "m-42-left medial";
  instance.items.push_back(test::item(1, test::rectangle(150, 150), 1, {0}));
  instance.items.back().label = "#1 38R";
  instance.items.push_back(test::item(2, test::rectangle(500, 150), 1, {0}));
  instance.items.back().label = "m-44-right lateral";
  Layout layout;
  layout.instance = instance.name;
  layout.strip_length = 200;
  layout.placements.push_back({0, -1, 0, 0, false, 5, 5});
  layout.placements.push_back({1, -1, 0, 0, false, 45, 5});
  layout.unplaced.push_back({2, 1, "too long"});
  const std::string svg = layout_svg(layout, instance);
  EXPECT_NE(svg.find(">m-42-left</text>"), std::string::npos) << svg;
  EXPECT_NE(svg.find(">medial</text>"), std::string::npos) << svg;
  EXPECT_NE(svg.find(">#1 38R</text>"), std::string::npos) << svg;  // fits: one line
  EXPECT_NE(svg.find("NOT PLACED: m-44-right lateral (item 2) x1: too long"), std::string::npos) << svg;
}

TEST(LayoutSvg, DrawnLinesAreThinDashedLinesTurnedWithTheirPiece) {
  NestInstance instance;
  instance.name = "lines";
  instance.strip_height = 200;
  instance.items.push_back(test::item(0, test::rectangle(100, 50), 1, {90}));
  instance.items.back().drawn_lines_mm = {{{10, 20}, {90, 20}, {90, 40}}};
  Layout layout;
  layout.instance = instance.name;
  layout.strip_length = 200;
  layout.placements.push_back({0, -1, 0, 90, false, 100, 5});
  const std::string svg = layout_svg(layout, instance);
  // (x, y) turned by 90 deg is (-y, x), then moved by (100, 5).
  const size_t line = svg.find("<polyline points=\"80,15 80,95 60,95 \"");
  ASSERT_NE(line, std::string::npos) << svg;
  EXPECT_NE(svg.substr(line, svg.find('>', line) - line).find("stroke-dasharray"), std::string::npos) << svg;
}

}  // namespace
}  // namespace lastcut
