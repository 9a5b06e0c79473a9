// The independent checker must catch every kind of bad layout (so that the nester tests can rely on it).
#include <gtest/gtest.h>

#include "engine/nest/layout_check.hpp"
#include "nest_test_instances.hpp"

namespace lastcut {
namespace {

NestInstance two_squares(double strip_height = 100) {
  NestInstance instance;
  instance.name = "two";
  instance.strip_height = strip_height;
  instance.items.push_back(test::item(0, test::rectangle(10, 10), 2, {0, 90}));
  return instance;
}

Layout strip_layout(std::vector<Placement> placements, double length) {
  Layout layout;
  layout.instance = "two";
  layout.strip_length = length;
  layout.placements = std::move(placements);
  return layout;
}

bool mentions(const std::vector<std::string>& problems, const std::string& words) {
  for (const auto& p : problems)
    if (p.find(words) != std::string::npos) return true;
  return false;
}

TEST(LayoutCheck, AcceptsAValidLayout) {
  const NestInstance instance = two_squares();
  Layout layout = strip_layout({{0, -1, 0, 0, false, 0, 0}, {0, -1, 0, 90, false, 20.5, 0}}, 20.5);
  update_utilisation(layout, instance);
  EXPECT_EQ(check_layout(layout, instance), std::vector<std::string>{});
  EXPECT_NEAR(layout.utilisation, 200.0 / (100 * 20.5), 1e-12);
}

TEST(LayoutCheck, FindsOverlapGapAndStripProblems) {
  NestInstance instance = two_squares();
  Layout overlap = strip_layout({{0, -1, 0, 0, false, 0, 0}, {0, -1, 0, 0, false, 9, 5}}, 19);
  update_utilisation(overlap, instance);
  EXPECT_TRUE(mentions(check_layout(overlap, instance), "overlap"));
  Layout apart = strip_layout({{0, -1, 0, 0, false, 0, 0}, {0, -1, 0, 0, false, 11, 0}}, 21);
  update_utilisation(apart, instance);
  EXPECT_TRUE(check_layout(apart, instance).empty());
  EXPECT_TRUE(mentions(check_layout(apart, instance, 1.5), "closer than the gap"));
  EXPECT_TRUE(check_layout(apart, instance, 0.9).empty());
  Layout outside = strip_layout({{0, -1, 0, 0, false, 0, 95}, {0, -1, 0, 0, false, 11, 0}}, 21);
  update_utilisation(outside, instance);
  EXPECT_TRUE(mentions(check_layout(outside, instance), "sticks out of the strip"));
  EXPECT_TRUE(mentions(check_layout(apart, instance, 0, 0.5), "sticks out of the strip"));  // margin
  Layout wrong_length = apart;
  wrong_length.strip_length = 15;
  update_utilisation(wrong_length, instance);
  EXPECT_TRUE(mentions(check_layout(wrong_length, instance), "sticks out"));
  Layout wrong_utilisation = apart;
  wrong_utilisation.utilisation = 0.99;
  EXPECT_TRUE(mentions(check_layout(wrong_utilisation, instance), "utilisation"));
}

TEST(LayoutCheck, FindsRotationMirrorGrainAndCountProblems) {
  NestInstance instance = two_squares();
  Layout rotated = strip_layout({{0, -1, 0, 45, false, 20, 20}, {0, -1, 0, 0, false, 40, 0}}, 60);
  update_utilisation(rotated, instance);
  EXPECT_TRUE(mentions(check_layout(rotated, instance), "rotation 45"));
  Layout mirrored = strip_layout({{0, -1, 0, 0, true, 10, 0}, {0, -1, 0, 0, false, 20, 0}}, 30);
  update_utilisation(mirrored, instance);
  EXPECT_TRUE(mentions(check_layout(mirrored, instance), "mirror"));
  instance.items[0].grain_deg = 0;
  instance.items[0].grain_tolerance_deg = 10;
  Layout across = strip_layout({{0, -1, 0, 90, false, 10, 0}, {0, -1, 0, 0, false, 20, 0}}, 30);
  update_utilisation(across, instance);
  EXPECT_TRUE(mentions(check_layout(across, instance), "grain"));
  Layout missing = strip_layout({{0, -1, 0, 0, false, 0, 0}}, 10);
  update_utilisation(missing, instance);
  EXPECT_TRUE(mentions(check_layout(missing, instance), "demand 2"));
  missing.unplaced.push_back({0, 1, "no room"});
  EXPECT_TRUE(check_layout(missing, instance).empty());
  Layout unknown = strip_layout({{5, -1, 0, 0, false, 0, 0}}, 10);
  EXPECT_TRUE(mentions(check_layout(unknown, instance), "unknown item"));
}

TEST(LayoutCheck, FindsHideDefectZoneAndEdgeProblems) {
  NestInstance instance = test::small_hide();
  instance.items[0].demand = 1;
  instance.items[1].demand = 0;
  auto check_at = [&](double x, double y, double margin = -1) {
    Layout layout;
    layout.placements.push_back({0, 7, 0, 0, false, x, y});
    update_utilisation(layout, instance);
    return check_layout(layout, instance, -1, margin);
  };
  EXPECT_TRUE(check_at(40, 60).empty());
  EXPECT_TRUE(mentions(check_at(160, 120), "defect"));
  EXPECT_TRUE(mentions(check_at(305, 210), "zone"));  // min_quality 2 on a quality-1 zone
  EXPECT_TRUE(mentions(check_at(-5, 60), "sticks out of hide"));
  EXPECT_TRUE(mentions(check_at(40, 60, 40), "sticks out of hide"));  // margin
  instance.items[0].min_quality = 1;
  EXPECT_TRUE(check_at(305, 210).empty());
  Layout wrong_bin;
  wrong_bin.placements.push_back({0, 3, 0, 0, false, 40, 60});
  EXPECT_TRUE(mentions(check_layout(wrong_bin, instance), "unknown hide"));
}

}  // namespace
}  // namespace lastcut
