// `lastcut nest MOLDS --hides HIDE...` (docs/hides.md): mold DXFs nested on hide files (DXF and
// JSON) through the same batch entry as lastcutd. The molds of one command are one job, so they
// go on one hide together: on a hide too small for all of them, none; the layout passes the
// independent checker and keeps to the rotation step.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "engine/core/dxf_document.hpp"
#include "engine/mold/mold_dxf.hpp"
#include "engine/nest/layout_check.hpp"
#include "engine/nest/nest_json.hpp"
#include "tests/support/lastcut_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

Polygon2 rectangle(double w, double h) { return {{{0, 0}, {w, 0}, {w, h}, {0, h}}}; }

TEST(NestHidesCli, MoldsGoWholeOnOneHideFile) {
  const lastcut::test::TempDir dir("nest-hides");
  std::filesystem::create_directories(dir / "m-40-left");
  write_mold_dxf(dir / "m-40-left" / "medial.dxf", Mold{"medial", rectangle(200, 80), {}});
  write_mold_dxf(dir / "m-40-left" / "lateral.dxf", Mold{"lateral", rectangle(200, 90), {}});
  // Hide A: 300 x 200 mm = 0.06 m^2 < the four pieces' 68000 mm^2: the job cannot go on it whole.
  DxfDocument small(DxfVersion::R12, {{"HIDE", 7}});
  small.polyline("HIDE", rectangle(300, 200).points, true);
  std::ofstream(dir / "a.dxf") << small.str();
  // Hide B: 600 x 400 mm with a hole in its middle.
  std::ofstream(dir / "b.json") << R"({"shape": {"type": "polygon", "data": {"outer": [[0,0],[600,0],[600,400],[0,400]],
      "inner": [[[280,180],[320,180],[320,220],[280,220]]]}}})";
  const test::CommandRun result = test::run_lastcut(
      "nest " + (dir / "m-40-left").string() + " --mirrored-twins --time-limit 0.5 --threads 1 --gap 2 " +
          "--rotation-step 90 -o " + (dir / "layout.json").string() + " --hides " + (dir / "a.dxf").string() + " " +
          (dir / "b.json").string(),
      dir);
  ASSERT_EQ(result.exit_code, 0) << result.all();
  const nlohmann::json json = read_json_file(dir / "layout.json");
  const Layout layout = layout_from_json(json);
  const NestInstance instance = instance_from_layout_json(json);
  EXPECT_EQ(check_layout(layout, instance), std::vector<std::string>{});
  ASSERT_EQ(instance.bins.size(), 2u);
  EXPECT_EQ(instance.bins[1].holes.size(), 1u);
  ASSERT_EQ(layout.placements.size(), 4u);
  std::set<int> bins;
  for (const Placement& p : layout.placements) {
    bins.insert(p.bin);
    EXPECT_EQ(std::fmod(p.rotation_deg, 90.0), 0.0) << p.rotation_deg;
  }
  EXPECT_EQ(bins, std::set<int>{1}) << "all on hide B, none on A";
  EXPECT_NE(result.all().find("4 of 4 pieces on 1 hide(s)"), std::string::npos) << result.all();

  // A bad hide file: one line, exit 1.
  DxfDocument open(DxfVersion::R12, {{"HIDE", 7}});
  open.polyline("HIDE", rectangle(600, 400).points, false);
  std::ofstream(dir / "open.dxf") << open.str();
  const test::CommandRun bad =
      test::run_lastcut("nest " + (dir / "m-40-left").string() + " --time-limit 0.5 -o " + (dir / "x.json").string() +
                            " --hides " + (dir / "open.dxf").string(),
                        dir);
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_EQ(bad.out, "");
  EXPECT_EQ(bad.err, "lastcut nest: error: " + (dir / "open.dxf").string() +
                         ": the hide outline on layer HIDE is open; close it in the drawing program\n");
}

}  // namespace
}  // namespace lastcut
