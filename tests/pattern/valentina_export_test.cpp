// A pattern set written by another program, cut end to end (issue 35): Valentina (Debian's
// `valentina` 0.7.52, installed by scripts/setup.sh) exports the hand-written pattern
// tests/pattern/data/quarter-tongue.val as DXF-AAMA R12 from its command line, headless
// (QT_QPA_PLATFORM=offscreen, format 16, --exportOnlyDetails); lastcut reads the export and
// `lastcut nest` cuts it on a roll. The areas are checked against ezdxf's reading of the same export
// (aama_ezdxf_report.py: the shoelace area of each block's closed layer-1 polyline) and, for the
// rectangular tongue, against arithmetic: 70 x 110 mm with a 4 mm seam allowance is 78 x 118 mm.
// A missing valentina or ezdxf fails the test (an install step missing), never skips it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/nest/layout_check.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/pattern/aama_dxf.hpp"
#include "tests/support/child_process.hpp"
#include "tests/support/lastcut_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut::test {
namespace {

constexpr double kAreaTolerance = 1e-4;  // relative: 0.01 %

double area_of(const std::vector<Point2>& outline) { return std::abs(signed_area(Polygon2{outline})); }

// Runs argv; a failure (also: the program is not installed, exit 127) fails the test with its log.
void run(const std::vector<std::string>& argv, const std::filesystem::path& log) {
  const int status = run_to_exit(argv, log, 300.0);
  ASSERT_EQ(status, 0) << argv[0] << " " << argv[1] << " failed; its output:\n" << read_text(log);
}

TEST(ValentinaExport, CutEndToEnd) {
  const TempDir dir("valentina");
  // Valentina leaves a backup of the pattern beside it when it converts the file's format version:
  // it works on a copy, never on the source tree.
  std::filesystem::copy_file(std::string(LASTCUT_SOURCE_DIR) + "/tests/pattern/data/quarter-tongue.val", dir / "shoe.val");
  run({"/usr/bin/env", "QT_QPA_PLATFORM=offscreen", "valentina", "--basename", "shoe", "--destination", dir.path().string(),
       "--format", "16", "--exportOnlyDetails", (dir / "shoe.val").string()},
      dir / "valentina.log");
  const std::filesystem::path exported = dir / "shoe_1.dxf";  // Valentina numbers its export files
  ASSERT_TRUE(std::filesystem::exists(exported)) << read_text(dir / "valentina.log");

  run({"/usr/bin/python3", std::string(LASTCUT_SOURCE_DIR) + "/tests/pattern/aama_ezdxf_report.py", exported.string(),
       (dir / "ezdxf.json").string()},
      dir / "ezdxf.log");
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(dir / "ezdxf.json"));
  EXPECT_EQ(report["dxfversion"], "AC1009");
  ASSERT_EQ(report["pieces"].size(), 2u);
  std::map<std::string, double> ezdxf_area;  // by block name
  for (const nlohmann::json& piece : report["pieces"]) {
    ASSERT_EQ(piece["cut_areas"].size(), 1u) << piece.dump();
    ezdxf_area[piece["block"]] = piece["cut_areas"][0].get<double>();
  }
  EXPECT_NEAR(ezdxf_area["TONGUE"], 78.0 * 118.0, 1e-6);

  // Valentina writes the pieces in no fixed order (one run the quarter first, the next the tongue).
  std::vector<PatternPiece> pieces = read_aama_dxf(exported);
  ASSERT_EQ(pieces.size(), 2u);
  std::sort(pieces.begin(), pieces.end(), [](const PatternPiece& a, const PatternPiece& b) { return a.name < b.name; });
  const PatternPiece& quarter = pieces[0];
  const PatternPiece& tongue = pieces[1];
  EXPECT_EQ(quarter.name, "quarter");
  EXPECT_EQ(quarter.quantity, 2);
  EXPECT_EQ(tongue.name, "tongue");
  EXPECT_EQ(tongue.quantity, 1);
  for (const PatternPiece& piece : pieces) {
    const double reference = ezdxf_area[piece.name == "quarter" ? "QUARTER" : "TONGUE"];
    EXPECT_NEAR(area_of(piece.cut_line_mm), reference, kAreaTolerance * reference) << piece.name;
    EXPECT_TRUE(piece.grain_line_mm) << piece.name;
    EXPECT_FALSE(piece.internal_lines_mm.empty()) << piece.name << ": the seam line, drawn on layer 8";
  }
  // The passmark at A4, 90 mm along the bottom edge: a LINE on layer 4 from the cut line into the piece.
  ASSERT_EQ(quarter.notches.size(), 1u);
  EXPECT_LT((quarter.notches[0].inward - Point2(0, 1)).norm(), 1e-6);
  EXPECT_EQ(tongue.notches.size(), 0u);
  // The quarter's grain runs along its length, the tongue's along its height.
  ASSERT_TRUE(quarter.grain_line_mm && tongue.grain_line_mm);
  const Point2 quarter_grain = (*quarter.grain_line_mm)[1] - (*quarter.grain_line_mm)[0];
  const Point2 tongue_grain = (*tongue.grain_line_mm)[1] - (*tongue.grain_line_mm)[0];
  EXPECT_NEAR(quarter_grain.y(), 0.0, 1e-6);
  EXPECT_NEAR(tongue_grain.x(), 0.0, 1e-6);

  // Cut: the export itself given to `lastcut nest`, two sets on a 500 mm roll.
  const CommandRun nest = run_lastcut("nest " + exported.string() + " --roll-width 500 --copies 2 --gap 2 --time-limit 0.5 --threads 1 -o " +
                                          (dir / "layout.json").string(),
                                      dir);
  ASSERT_EQ(nest.exit_code, 0) << nest.all();
  const nlohmann::json json = read_json_file(dir / "layout.json");
  const Layout layout = layout_from_json(json);
  const NestInstance instance = instance_from_layout_json(json);
  EXPECT_EQ(check_layout(layout, instance), std::vector<std::string>{});
  std::map<std::string, int> placed;
  for (const Placement& p : layout.placements)
    for (const NestItem& item : instance.items)
      if (item.id == p.item) ++placed[item.label];
  EXPECT_EQ(placed, (std::map<std::string, int>{{"quarter", 4}, {"tongue", 2}}));
  for (const NestItem& item : instance.items) {
    const double reference = ezdxf_area[item.label == "quarter" ? "QUARTER" : "TONGUE"];
    EXPECT_NEAR(area_of(item.shape.points), reference, kAreaTolerance * reference) << item.label;
    std::cout << item.label << ": " << area_of(item.shape.points) << " mm^2 cut, ezdxf " << reference << " mm^2, difference "
              << 100 * std::abs(area_of(item.shape.points) - reference) / reference << " %\n";
  }
}

}  // namespace
}  // namespace lastcut::test
