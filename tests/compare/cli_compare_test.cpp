// `lastcut compare` as an operator runs it: the real binary on a real mold (a generated last,
// flattened by `lastcut flatten`) against references written as files.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "engine/mold/mold_dxf.hpp"
#include "tests/support/lastcut_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

using test::CommandRun;
using test::read_text;

class CliCompare : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = lastcut::test::make_temp_dir("cli-compare");
    ASSERT_EQ(run("generate -o '" + (dir_ / "last.stl").string() + "' --size 40 --side left --triangles 20000").exit_code, 0);
    ASSERT_EQ(run("flatten '" + (dir_ / "last.stl").string() + "' -o '" + (dir_ / "flat").string() + "'").exit_code, 0);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static CommandRun run(const std::string& arguments) { return test::run_lastcut(arguments, dir_); }

  // The medial mold's outline as an SVG pattern in mm: mirrored (a pattern of the other foot),
  // with the toe corner pulled `pull_mm` along the outline's heel->toe direction.
  static fs::path write_svg_reference(const std::string& name, double pull_mm) {
    const Mold mold = read_mold_dxf(dir_ / "flat" / "medial.dxf");
    Point2 heel = Point2::Zero(), toe = Point2::Zero();
    for (const auto& mark : mold.marks) {
      if (mark.name == "heel") heel = mark.position_mm;
      if (mark.name == "toe") toe = mark.position_mm;
    }
    const Point2 pull = pull_mm * (toe - heel).normalized();
    std::string d;
    for (const auto& p : mold.outline.points) {
      const Point2 q = p + std::max(0.0, 1.0 - (p - toe).norm() / 20.0) * pull;
      // Mirrored in x; SVG's y points down, the reader flips it back.
      d += (d.empty() ? "M " : " L ") + std::to_string(-q.x()) + "," + std::to_string(-q.y());
    }
    const fs::path path = dir_ / name;
    std::ofstream(path) << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1000mm\" height=\"1000mm\" "
                           "viewBox=\"-500 -500 1000 1000\">\n<path fill=\"none\" stroke=\"black\" d=\""
                        << d << " Z\"/>\n</svg>\n";
    return path;
  }

  static inline fs::path dir_;
};

TEST_F(CliCompare, MoldAgainstItselfPasses) {
  const fs::path out = dir_ / "self";
  const CommandRun run_result = run("compare '" + (dir_ / "flat").string() + "' '" + (dir_ / "flat" / "medial.dxf").string() +
                                    "' --mold medial -o '" + out.string() + "'");
  ASSERT_EQ(run_result.exit_code, 0) << run_result.out << run_result.err;
  EXPECT_NE(run_result.out.find("overlap     100.00 %"), std::string::npos) << run_result.out;
  const auto json = nlohmann::json::parse(read_text(out / "compare.json"));
  EXPECT_GE(json["overlap_pct"].get<double>(), 99.995);
  ASSERT_EQ(json["corners"].size(), 4u);
  for (const auto& corner : json["corners"]) {
    EXPECT_LT(corner["margin_mm"].get<double>(), 0.01) << corner.dump();
    EXPECT_EQ(corner["source"], "reference mark");
  }
  EXPECT_TRUE(json["within_tolerance"].get<bool>());
  EXPECT_NE(read_text(out / "compare.svg").find("</svg>"), std::string::npos);
}

TEST_F(CliCompare, MirroredSvgPatternFindsCornersGeometrically) {
  const fs::path out = dir_ / "svg";
  const CommandRun run_result = run("compare '" + (dir_ / "flat" / "medial.dxf").string() + "' '" +
                                    write_svg_reference("pattern.svg", 0.0).string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(run_result.exit_code, 0) << run_result.out << run_result.err;
  const auto json = nlohmann::json::parse(read_text(out / "compare.json"));
  EXPECT_TRUE(json["motion"]["mirrored"].get<bool>());
  EXPECT_GE(json["overlap_pct"].get<double>(), 99.99);
  for (const auto& corner : json["corners"]) {
    EXPECT_EQ(corner["source"], "sharp corner") << corner.dump();
    EXPECT_LT(corner["margin_mm"].get<double>(), 0.05) << corner.dump();
  }
}

TEST_F(CliCompare, MovedToeExitsThreeBeyondTolerance) {
  const fs::path reference = write_svg_reference("pattern-toe.svg", 5.0);
  const fs::path out = dir_ / "toe";
  const CommandRun run_result = run("compare '" + (dir_ / "flat" / "medial.dxf").string() + "' '" + reference.string() +
                                    "' -o '" + out.string() + "'");
  EXPECT_EQ(run_result.exit_code, 3) << run_result.out << run_result.err;
  EXPECT_NE(run_result.out.find("corner toe is "), std::string::npos) << run_result.out;
  const auto json = nlohmann::json::parse(read_text(out / "compare.json"));
  EXPECT_FALSE(json["within_tolerance"].get<bool>());
  for (const auto& corner : json["corners"]) {
    if (corner["name"] == "toe") EXPECT_NEAR(corner["margin_mm"].get<double>(), 5.0, 0.1);
    else EXPECT_LT(corner["margin_mm"].get<double>(), 0.5) << corner.dump();
  }
  EXPECT_TRUE(fs::exists(out / "compare.svg"));
  // With a tolerance above the 5 mm the same comparison passes.
  EXPECT_EQ(run("compare '" + (dir_ / "flat" / "medial.dxf").string() + "' '" + reference.string() + "' -o '" +
                out.string() + "' --tolerance 6")
                .exit_code,
            0);
}

TEST_F(CliCompare, RefusalsAreOneLine) {
  const auto expect_one_line = [](const CommandRun& r, int code, const std::string& text) {
    EXPECT_EQ(r.exit_code, code) << r.out << r.err;
    EXPECT_TRUE(r.err.starts_with("lastcut: error: ")) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(text), std::string::npos) << r.err;
  };
  const std::string flat = (dir_ / "flat").string();
  expect_one_line(run("compare '" + flat + "' '" + flat + "/medial.dxf' -o '" + (dir_ / "x").string() + "'"), 1,
                  "holds 2 molds (medial, lateral); pick one with --mold");
  std::ofstream(dir_ / "notes.txt") << "toe 3 mm\n";
  expect_one_line(run("compare '" + flat + "/medial.dxf' '" + (dir_ / "notes.txt").string() + "'"), 1,
                  "notes.txt: not a pattern file; expected a .dxf or .svg outline");
  expect_one_line(run("compare '" + flat + "/medial.dxf' '" + flat + "/lateral.dxf' --tolerance -1"), 2,
                  "tolerance must be between 0 and 100 mm");
  EXPECT_FALSE(fs::exists(dir_ / "x" / "compare.json"));
  const CommandRun help = run("compare --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("3: a margin beyond it"), std::string::npos) << help.out;
}

}  // namespace
}  // namespace lastcut
