// `lastcut nest PATTERN.dxf` (docs/aama-dxf.md): a DXF-AAMA pattern set written by lastcut's own
// writer, nested by the real binary on a roll and on a hide with a backbone and a poor zone. Each
// piece's demand (its Quantity x the sets) is placed; the layout read back from the written JSON
// passes the independent checker; and, taken from the pattern file itself rather than from the
// items the command made, every placed grain line lies within the tolerance of the backbone. Bad
// pattern files are refused with the reader's one line and exit 1, nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "engine/nest/layout_check.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/pattern/aama_dxf.hpp"
#include "tests/pattern/aama_test_files.hpp"
#include "tests/support/lastcut_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

// A derby's set: the vamp (grain along x), four quarters whose grain line is drawn at 30 degrees,
// two linings without a grain line (free).
std::vector<PatternPiece> derby_set() {
  PatternPiece vamp = test::sample_piece("vamp", "42", Point2(0, 0), 120, 80);
  PatternPiece quarter = test::sample_piece("quarter", "42", Point2(0, 0), 90, 45);
  quarter.quantity = 4;
  quarter.grain_line_mm = std::array<Point2, 2>{Point2(0, 0), Point2(std::cos(M_PI / 6), std::sin(M_PI / 6)) * 60.0};
  PatternPiece lining = test::sample_piece("lining", "42", Point2(0, 0), 90, 40);
  lining.category = "lining";
  lining.grain_line_mm.reset();
  return {vamp, quarter, lining};
}

// Placements per item label, and the checker's verdict on the layout as written.
struct WrittenLayout {
  Layout layout;
  NestInstance instance;
  std::map<std::string, int> placed;  // label -> copies placed
};

WrittenLayout read_written(const std::filesystem::path& file) {
  const nlohmann::json json = read_json_file(file);
  WrittenLayout written{layout_from_json(json), instance_from_layout_json(json), {}};
  for (const Placement& p : written.layout.placements)
    for (const NestItem& item : written.instance.items)
      if (item.id == p.item) ++written.placed[item.label];
  return written;
}

TEST(NestPatternCli, PatternSetOnARoll) {
  const test::TempDir dir("nest-pattern");
  write_aama_dxf(dir / "derby-42.dxf", derby_set());
  const test::CommandRun run = test::run_lastcut("nest " + (dir / "derby-42.dxf").string() +
                                                     " --roll-width 600 --copies 2 --gap 2 --time-limit 1 --threads 1 -o " +
                                                     (dir / "layout.json").string() + " --svg " + (dir / "layout.svg").string(),
                                                 dir);
  ASSERT_EQ(run.exit_code, 0) << run.all();
  EXPECT_NE(run.out.find("derby-42: 16 of 16 pieces on a strip"), std::string::npos) << run.out;
  const WrittenLayout written = read_written(dir / "layout.json");
  EXPECT_EQ(check_layout(written.layout, written.instance), std::vector<std::string>{});
  EXPECT_TRUE(written.layout.unplaced.empty());
  // Quantity x 2 sets each.
  EXPECT_EQ(written.placed, (std::map<std::string, int>{{"vamp 42", 4}, {"quarter 42", 8}, {"lining 42", 4}}));
  ASSERT_EQ(written.instance.items.size(), 3u);
  for (const NestItem& item : written.instance.items) {
    EXPECT_EQ(item.marks.size(), 3u) << item.label << ": the notches are the item's marks";
    EXPECT_FALSE(item.grain_deg) << item.label << ": no --grain-tolerance, grain free";
  }
}

TEST(NestPatternCli, PatternSetOnAHideWithABackbone) {
  const test::TempDir dir("nest-pattern");
  const std::vector<PatternPiece> pieces = derby_set();
  write_aama_dxf(dir / "derby-42.dxf", pieces);
  // 1100 x 800 mm, backbone along y; its left strip is grade 1 (belly), which --min-quality 2 avoids.
  std::ofstream(dir / "hide.json") << R"({"name": "CALF-7", "backbone_deg": 90,
      "shape": {"type": "polygon", "data": {"outer": [[0,0],[1100,0],[1100,800],[0,800]], "inner": []}},
      "zones": [{"quality": 1, "shape": {"type": "simple_polygon", "data": [[0,0],[150,0],[150,800],[0,800]]}}]})";
  const double tolerance_deg = 5;
  const test::CommandRun run = test::run_lastcut(
      "nest " + (dir / "derby-42.dxf").string() + " --hides " + (dir / "hide.json").string() +
          " --grain-tolerance 5 --min-quality 2 --mirrored-twins --gap 2 --time-limit 1 --threads 1 -o " +
          (dir / "layout.json").string(),
      dir);
  ASSERT_EQ(run.exit_code, 0) << run.all();
  EXPECT_NE(run.out.find("16 of 16 pieces on 1 hide(s)"), std::string::npos) << run.out;
  const WrittenLayout written = read_written(dir / "layout.json");
  EXPECT_EQ(check_layout(written.layout, written.instance), std::vector<std::string>{});
  EXPECT_EQ(written.placed, (std::map<std::string, int>{{"vamp 42", 2},
                                                        {"vamp 42 (other foot)", 2},
                                                        {"quarter 42", 4},
                                                        {"quarter 42 (other foot)", 4},
                                                        {"lining 42", 2},
                                                        {"lining 42 (other foot)", 2}}));
  // The grain as the pattern file draws it, turned as placed: within 5 degrees of the backbone (an
  // axis: either direction). The twin is the piece mirrored x -> -x.
  int grains_checked = 0;
  for (const Placement& p : written.layout.placements) {
    const NestItem& item = *std::find_if(written.instance.items.begin(), written.instance.items.end(),
                                         [&](const NestItem& i) { return i.id == p.item; });
    EXPECT_GE(item.min_quality, 2) << item.label;
    const PatternPiece& piece = *std::find_if(pieces.begin(), pieces.end(), [&](const PatternPiece& candidate) {
      return item.label.rfind(candidate.name + " ", 0) == 0;
    });
    if (!piece.grain_line_mm) {
      EXPECT_FALSE(item.grain_deg) << item.label;
      continue;
    }
    const bool twin = item.label.find("(other foot)") != std::string::npos;
    Point2 along = (*piece.grain_line_mm)[1] - (*piece.grain_line_mm)[0];
    if (twin) along.x() = -along.x();
    if (p.mirrored) along.x() = -along.x();
    const double placed_deg = std::atan2(along.y(), along.x()) * 180 / M_PI + p.rotation_deg;
    const double off_deg = std::abs(std::remainder(placed_deg - 90, 180.0));
    EXPECT_LE(off_deg, tolerance_deg + 1e-6) << item.label << " at " << p.rotation_deg << " deg";
    ++grains_checked;
  }
  EXPECT_EQ(grains_checked, 12);
}

std::string refusal_line(const test::TempDir& dir, const std::string& name, const std::string& content) {
  std::ofstream(dir / name) << content;
  const test::CommandRun run = test::run_lastcut(
      "nest " + (dir / name).string() + " --roll-width 600 --time-limit 0.2 -o " + (dir / "out.json").string(), dir);
  EXPECT_EQ(run.exit_code, 1) << name;
  EXPECT_EQ(run.out, "") << name;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.json")) << name;
  return run.err;
}

TEST(NestPatternCli, BadPatternFilesAreRefusedWithOneLine) {
  using test::HandDxf;
  const test::TempDir dir("nest-pattern");
  const std::string prefix = "lastcut nest: error: " + dir.path().string() + "/";
  const auto closed_square = [](HandDxf& d) { d.polyline("1", test::square(100), true); };
  EXPECT_EQ(refusal_line(dir, "open.dxf", test::one_piece_file(4, [](HandDxf& d) { d.polyline("1", test::square(100), false); })),
            prefix + "open.dxf: piece \"vamp\": its cut line on layer 1 is open\n");
  HandDxf undefined;
  undefined.header(4).section("BLOCKS").block("vamp").polyline("1", test::square(100), true).end_block().end_section();
  undefined.section("ENTITIES").insert("vamp", Point2(0, 0)).insert("heel", Point2(200, 0)).end_section().eof();
  EXPECT_EQ(refusal_line(dir, "missing-block.dxf", undefined.str()),
            prefix + "missing-block.dxf: an INSERT places block \"heel\", which the BLOCKS section does not define\n");
  HandDxf unplaced;  // piece blocks, but nothing places them
  unplaced.header(4).section("BLOCKS").block("vamp").polyline("1", test::square(100), true).end_block().end_section();
  unplaced.section("ENTITIES").end_section().eof();
  EXPECT_EQ(refusal_line(dir, "unplaced.dxf", unplaced.str()),
            prefix + "unplaced.dxf: no piece blocks (DXF-AAMA places each piece as a BLOCK with an INSERT)\n");
  EXPECT_EQ(refusal_line(dir, "furlong.dxf", test::one_piece_file(0, [&](HandDxf& d) {
                           closed_square(d);
                           d.text("1", "Units: FURLONG");
                         })),
            prefix + "furlong.dxf: unknown units \"Units: FURLONG\" (METRIC, MM, CM, ENGLISH or INCH)\n");
  EXPECT_EQ(refusal_line(dir, "two.dxf", test::one_piece_file(4, [&](HandDxf& d) {
                           closed_square(d);
                           d.text("1", "Quantity: two");
                         })),
            prefix + "two.dxf: piece \"vamp\": quantity 'two' is not a positive count\n");
  // A drawing of neither kind is still a mold to the command, refused as before pattern sets.
  HandDxf neither;
  neither.header(4).section("ENTITIES").line("0", Point2(0, 0), Point2(10, 0)).end_section().eof();
  EXPECT_EQ(refusal_line(dir, "lines.dxf", neither.str()), prefix + "lines.dxf: no closed outline on layer CUT\n");
}

}  // namespace
}  // namespace lastcut
