// JSON I/O: the shared benchmark files parse, layouts round-trip with their embedded instance, and
// bad input is refused with one readable line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>

#include "engine/core/engine_error.hpp"
#include "engine/nest/layout_check.hpp"
#include "engine/nest/nest_json.hpp"
#include "nest_test_instances.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

const std::filesystem::path kData = LASTCUT_SHARED_DATA_DIR "/nesting";

TEST(NestJson, ReadsEveryShippedInstance) {
  int files = 0;
  for (const char* folder : {"esicup", "leather"})
    for (const auto& entry : std::filesystem::directory_iterator(kData / folder)) {
      const NestInstance instance = read_nest_instance(entry.path());
      EXPECT_FALSE(instance.items.empty()) << entry.path();
      for (const NestItem& item : instance.items) EXPECT_GT(signed_area(item.shape), 0) << entry.path() << " item " << item.id;
      ++files;
    }
  EXPECT_EQ(files, 15);
  const NestInstance albano = read_nest_instance(kData / "esicup/albano.json");
  ASSERT_TRUE(albano.strip_height);
  EXPECT_DOUBLE_EQ(*albano.strip_height, 4900.0);
  EXPECT_EQ(albano.items[0].allowed_rotations_deg, (std::vector<double>{0, 180}));
  EXPECT_EQ(albano.items[0].shape.points.size(), 14u);  // closing point dropped
  const NestInstance hides = read_nest_instance(kData / "leather/baldacci3.json");
  EXPECT_FALSE(hides.strip_height);
  EXPECT_EQ(hides.bins.size(), 12u);
  EXPECT_EQ(hides.bins[0].holes.size(), 6u);
  EXPECT_FALSE(hides.bins[0].zones.empty());
  EXPECT_TRUE(hides.items[0].allowed_rotations_deg.empty());  // free rotation
}

TEST(NestJson, LayoutRoundTripIsSelfContained) {
  NestInstance instance = test::small_hide();
  instance.items[0].label = "order 12 size 42 L";
  instance.items[0].marks.push_back({"toe", {1, 2}, {3, 4}});
  instance.items[0].grain_deg = 90;
  instance.items[0].grain_tolerance_deg = 5;
  instance.items[1].allow_mirror = true;
  instance.gap_mm = 1.5;
  Layout layout;
  layout.instance = instance.name;
  layout.placements.push_back({0, 7, 0, 90, false, 50, 60});
  layout.placements.push_back({1, 7, 0, 180, true, 300, 100});
  layout.unplaced.push_back({0, 3, "no room left"});
  layout.unplaced.push_back({1, 2, "no room left"});
  update_utilisation(layout, instance);
  const nlohmann::json json = layout_to_json(layout, instance);
  EXPECT_EQ(json["placements"][0]["bin"], 7);
  EXPECT_FALSE(json.contains("strip_length"));
  const Layout back = layout_from_json(nlohmann::json::parse(json.dump()));
  const NestInstance embedded = instance_from_layout_json(nlohmann::json::parse(json.dump()));
  ASSERT_EQ(back.placements.size(), 2u);
  EXPECT_EQ(back.placements[1].mirrored, true);
  EXPECT_DOUBLE_EQ(back.placements[1].rotation_deg, 180);
  EXPECT_DOUBLE_EQ(back.utilisation, layout.utilisation);
  EXPECT_EQ(back.unplaced[0].reason, "no room left");
  ASSERT_EQ(embedded.items.size(), 2u);
  EXPECT_EQ(embedded.items[0].label, "order 12 size 42 L");
  EXPECT_EQ(embedded.items[0].marks[0].to_mm, Point2(3, 4));
  EXPECT_EQ(*embedded.items[0].grain_deg, 90);
  EXPECT_EQ(embedded.items[0].min_quality, 2);
  EXPECT_EQ(embedded.bins[0].holes.size(), 1u);
  EXPECT_EQ(embedded.bins[0].zones[0].quality, 1);
  EXPECT_DOUBLE_EQ(embedded.gap_mm, 1.5);
  // The same placed shapes from the original and from the embedded instance.
  EXPECT_TRUE(placed_shape(embedded.items[1], back.placements[1]).points[2].isApprox(
      placed_shape(instance.items[1], layout.placements[1]).points[2]));
}

TEST(NestJson, StripLayoutCarriesLengthAndHeight) {
  const NestInstance instance = test::small_strip();
  Layout layout;
  layout.instance = instance.name;
  layout.strip_length = 123.5;
  const nlohmann::json json = layout_to_json(layout, instance);
  EXPECT_DOUBLE_EQ(json["strip_length"].get<double>(), 123.5);
  EXPECT_DOUBLE_EQ(json["strip_height"].get<double>(), 100.0);
  EXPECT_FALSE(json["placements"].empty() && json.contains("bins"));
  EXPECT_DOUBLE_EQ(*instance_from_layout_json(json).strip_height, 100.0);
}

void expect_refused(const std::string& text, const std::string& words) {
  try {
    instance_from_json(nlohmann::json::parse(text), "bad.json");
    ADD_FAILURE() << "accepted: " << text;
  } catch (const EngineError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(words), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(NestJson, HideFieldsSurviveTheLayoutFile) {
  NestInstance instance = test::small_hide();
  instance.items[0].quality_regions.push_back({Polygon2{{{0, 0}, {10, 0}, {10, 5}}}, 3});
  instance.items[0].pair_group = "order 12";
  instance.items[1].pair_group = "order 12";
  instance.items[1].priority = 4;
  instance.bins[0].name = "H-0815";
  instance.bins[0].backbone_deg = 12.5;
  instance.bins[0].backbone_point = Point2(300, 140);
  instance.items[0].mirror_key = "job 4: 0 vamp";
  instance.pair_distance_mm = 250;
  Layout layout;
  layout.instance = instance.name;
  const NestInstance embedded = instance_from_layout_json(nlohmann::json::parse(layout_to_json(layout, instance).dump()));
  ASSERT_EQ(embedded.items[0].quality_regions.size(), 1u);
  EXPECT_EQ(embedded.items[0].quality_regions[0].min_quality, 3);
  EXPECT_EQ(embedded.items[0].quality_regions[0].shape.points[2], Point2(10, 5));
  EXPECT_EQ(embedded.items[1].pair_group, "order 12");
  EXPECT_EQ(embedded.items[1].priority, 4);
  EXPECT_EQ(embedded.items[0].priority, 0);
  EXPECT_EQ(embedded.bins[0].name, "H-0815");
  ASSERT_TRUE(embedded.bins[0].backbone_deg.has_value());
  EXPECT_DOUBLE_EQ(*embedded.bins[0].backbone_deg, 12.5);
  EXPECT_EQ(embedded.bins[0].backbone_point, Point2(300, 140));
  EXPECT_EQ(embedded.items[0].mirror_key, "job 4: 0 vamp");
  EXPECT_EQ(embedded.items[1].mirror_key, "");
  EXPECT_DOUBLE_EQ(embedded.pair_distance_mm, 250);
  expect_refused(R"({"strip_height": 10, "items": [{"id": 0, "mirror_key": 3, "shape": [[0,0],[1,0],[0,1]]}]})", "mirror_key");
  expect_refused(R"({"strip_height": 10, "items": [{"id": 0, "pair_group": 7, "shape": [[0,0],[1,0],[0,1]]}]})", "pair_group");
  expect_refused(R"({"strip_height": 10, "items": [{"id": 0, "quality_regions": [{"shape": [[0,0],[1,0],[0,1]]}], "shape": [[0,0],[1,0],[0,1]]}]})", "min_quality");
}

TEST(NestJson, DrawnLinesSurviveTheLayoutFileAndBadOnesAreRefused) {
  NestInstance instance = test::small_hide();
  instance.items[0].drawn_lines_mm = {{{1, 2}, {3, 4}, {5, 2.5}}, {{0, 0}, {1, 1}}};
  Layout layout;
  layout.instance = instance.name;
  const nlohmann::json json = layout_to_json(layout, instance);
  EXPECT_FALSE(json["items"][1].contains("drawn_lines")) << "an item without lines writes no key";
  const NestInstance embedded = instance_from_layout_json(nlohmann::json::parse(json.dump()));
  EXPECT_EQ(embedded.items[0].drawn_lines_mm, instance.items[0].drawn_lines_mm);
  EXPECT_TRUE(embedded.items[1].drawn_lines_mm.empty());
  const std::string item = R"({"strip_height": 10, "items": [{"id": 3, "shape": [[0,0],[1,0],[0,1]], "drawn_lines": )";
  auto refusal = [&](const std::string& lines) {
    try {
      instance_from_json(nlohmann::json::parse(item + lines + "}]}"), "bad.json");
    } catch (const EngineError& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal("7"), "bad.json item 3: \"drawn_lines\" must be a list of lines");
  EXPECT_EQ(refusal("[[[0,0],[1,1]], {}]"), "bad.json item 3 drawn line 1: a drawn line must be a list of [x, y] points");
  EXPECT_EQ(refusal("[[[0,0]]]"), "bad.json item 3 drawn line 0: has 1 points, at least 2 are needed");
  EXPECT_EQ(refusal("[[]]"), "bad.json item 3 drawn line 0: has 0 points, at least 2 are needed");
  EXPECT_EQ(refusal("[[[0,0],[1]]]"), "bad.json item 3 drawn line 0: a point must be [x, y]");
  EXPECT_EQ(refusal("[[[0,0],[1,\"a\"]]]"), "bad.json item 3 drawn line 0: expected a number, found string");
  // JSON has no NaN or infinity; an instance built in code and read back through its JSON does.
  nlohmann::json infinite = instance_to_json(instance);
  infinite["items"][0]["drawn_lines"][0][1][0] = std::numeric_limits<double>::infinity();
  try {
    instance_from_json(infinite, "bad.json");
    ADD_FAILURE() << "accepted an infinite coordinate";
  } catch (const EngineError& error) {
    EXPECT_EQ(std::string(error.what()), "bad.json item 0 drawn line 0: number is not finite");
  }
}

TEST(NestJson, RefusesBadInstances) {
  expect_refused(R"({"items": []})", "neither");
  expect_refused(R"({"strip_height": 10, "items": [{"id": 0, "shape": [[0,0],[1,0]]}]})", "at least 3");
  expect_refused(R"({"strip_height": 10, "items": [{"id": 0, "shape": [[0,0],[1,0],[2,0]]}]})", "zero area");
  expect_refused(R"({"strip_height": -1, "items": []})", "positive");
  expect_refused(R"({"strip_height": 10, "items": [{"id": 0, "demand": -2, "shape": [[0,0],[1,0],[0,1]]}]})", "negative");
  expect_refused(R"({"strip_height": 10, "items": [{"id": 0, "shape": [[0,0],[1,0],[0,1]]}, {"id": 0, "shape": [[0,0],[1,0],[0,1]]}]})", "twice");
  expect_refused(R"({"strip_height": 10, "items": [{"id": 0, "shape": [[0,0],["a",0],[0,1]]}]})", "number");
  expect_refused(R"({"strip_height": 10, "items": [{"id": 0, "shape": {"type": "circle", "data": []}}]})", "circle");
  expect_refused(R"({"strip_height": 10, "items": [{"id": 0, "allowed_orientations": [], "shape": [[0,0],[1,0],[0,1]]}]})", "no rotation");
  expect_refused(R"([1, 2])", "object");
  EXPECT_THROW(layout_from_json(nlohmann::json::parse(R"({"placements": [{"item": 0}]})")), EngineError);
  EXPECT_THROW(instance_from_layout_json(nlohmann::json::parse(R"({"placements": []})")), EngineError);
}

TEST(NestJson, RefusesFilesThatAreNotJson) {
  const test::TempDir folder("nest-json");
  const auto path = folder / "not-json.json";
  std::ofstream(path) << "{\"strip_height\": 10, \"items\": [";
  EXPECT_THROW(read_nest_instance(path), EngineError);
  EXPECT_THROW(read_nest_instance(path.string() + ".missing"), EngineError);
}

// Found by the nest_instance fuzz target: nlohmann's parser throws out_of_range, not parse_error,
// for a number no double holds; it escaped the reader instead of being refused.
TEST(NestJson, RefusesNumbersTooLargeForADouble) {
  const test::TempDir folder("nest-json");
  const auto path = folder / "huge-number.json";
  std::ofstream(path) << R"({"strip_height": 1e400, "items": []})";
  try {
    read_nest_instance(path);
    ADD_FAILURE() << "accepted";
  } catch (const EngineError& error) {
    EXPECT_NE(std::string(error.what()).find("number too large"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace lastcut
