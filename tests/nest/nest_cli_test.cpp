// The real `lastcut nest` binary: writes a layout that the independent checker accepts and a
// picture, exits 3 when pieces are left over, and refuses bad input with one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/mold/mold_dxf.hpp"
#include "engine/nest/layout_check.hpp"
#include "engine/nest/nest_json.hpp"
#include "nest_test_instances.hpp"
#include "tests/support/lastcut_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

TEST(NestCli, WritesACheckedLayoutAndPicture) {
  const lastcut::test::TempDir dir("nest-cli");
  std::ofstream(dir / "strip.json") << instance_to_json(test::small_strip()).dump();
  const test::CommandRun result =
      test::run_lastcut("nest " + (dir / "strip.json").string() + " --time-limit 1 --threads 2 --gap 1 -o " +
                            (dir / "layout.json").string() + " --svg " + (dir / "layout.svg").string(),
                        dir);
  ASSERT_EQ(result.exit_code, 0) << result.all();
  EXPECT_NE(result.all().find("10 of 10 pieces"), std::string::npos) << result.all();
  const nlohmann::json json = read_json_file(dir / "layout.json");
  const Layout layout = layout_from_json(json);
  const NestInstance embedded = instance_from_layout_json(json);
  EXPECT_DOUBLE_EQ(embedded.gap_mm, 1.0);  // the gap the layout was made with travels with it
  EXPECT_EQ(check_layout(layout, embedded), std::vector<std::string>{});
  std::ifstream svg(dir / "layout.svg");
  const std::string picture((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
  EXPECT_NE(picture.find("<svg"), std::string::npos);
  EXPECT_NE(picture.find("utilisation"), std::string::npos);
}

TEST(NestCli, ExitsThreeWhenPiecesAreLeftOver) {
  const lastcut::test::TempDir dir("nest-cli");
  NestInstance instance = test::small_hide();
  instance.items.push_back(test::item(5, test::rectangle(500, 40), 1, {}));
  std::ofstream(dir / "hide.json") << instance_to_json(instance).dump();
  const test::CommandRun result = test::run_lastcut(
      "nest " + (dir / "hide.json").string() + " --time-limit 0.5 --threads 1 -o " + (dir / "layout.json").string(),
      dir);
  EXPECT_EQ(result.exit_code, 3) << result.all();
  EXPECT_NE(result.all().find("not placed: item 5"), std::string::npos) << result.all();
}

TEST(NestCli, MoldsFromSeveralLastsCarryTheirFolderOnTheLabel) {
  // What `lastcut flatten` leaves: one folder per last, one DXF per half, labelled by the half only.
  const lastcut::test::TempDir dir("nest-cli");
  for (const std::string last : {"m-38-left", "m-40-right"}) {
    std::filesystem::create_directories(dir / last);
    write_mold_dxf(dir / last / "medial.dxf", Mold{"medial", test::rectangle(120, 60), {}});
  }
  const test::CommandRun result =
      test::run_lastcut("nest " + (dir / "m-38-left").string() + " " + (dir / "m-40-right").string() +
                            " --roll-width 300 --time-limit 0.5 --threads 1 -o " + (dir / "batch.json").string(),
                        dir);
  ASSERT_EQ(result.exit_code, 0) << result.all();
  const NestInstance embedded = instance_from_layout_json(read_json_file(dir / "batch.json"));
  EXPECT_EQ(embedded.name, "batch");  // several lasts: named after the layout, not the first last
  ASSERT_EQ(embedded.items.size(), 2u);
  EXPECT_EQ(embedded.items[0].label, "m-38-left medial");
  EXPECT_EQ(embedded.items[1].label, "m-40-right medial");
}

TEST(NestCli, RefusesBadInputWithOneLine) {
  const lastcut::test::TempDir dir("nest-cli");
  std::ofstream(dir / "broken.json") << "{\"strip_height\": 10, \"items\": [{\"id\": 0, \"shape\": [[0,0],[1,0]]}]}";
  const test::CommandRun bad = test::run_lastcut(
      "nest " + (dir / "broken.json").string() + " --time-limit 1 -o " + (dir / "out.json").string(), dir);
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_EQ(bad.out, "");
  EXPECT_EQ(bad.err.rfind("lastcut nest: error:", 0), 0u) << bad.err;
  EXPECT_NE(bad.err.find("at least 3"), std::string::npos) << bad.err;
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
  const test::CommandRun missing = test::run_lastcut(
      "nest " + (dir / "missing.json").string() + " --time-limit 1 -o " + (dir / "out.json").string(), dir);
  EXPECT_EQ(missing.exit_code, 1) << missing.all();
  const test::CommandRun molds_without_roll =
      test::run_lastcut("nest " + dir.path().string() + " --time-limit 1 -o " + (dir / "out.json").string(), dir);
  EXPECT_EQ(molds_without_roll.exit_code, 1) << molds_without_roll.all();
}

}  // namespace
}  // namespace lastcut
