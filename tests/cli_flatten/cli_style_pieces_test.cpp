// `lastcut style pieces` as a shop runs it: the real binary, the shipped derby style folder and a
// generated last of another size, posed. Checked on the files it writes: four pieces, each a DXF with
// one closed cut line (read back by the mold reader) whose area exceeds its net's by the allowances,
// pieces.json's pieces covering the upper's area within 0.1 %. A style folder with a mistake is
// refused with one line naming the key and its line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "engine/mold/mold_dxf.hpp"
#include "engine/pattern/aama_dxf.hpp"
#include "tests/support/child_process.hpp"
#include "tests/support/lastcut_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

const fs::path kDerby = fs::path(LASTCUT_SOURCE_DIR) / "config" / "styles" / "derby";

TEST(CliStylePieces, ShippedDerbyOnAnotherLast) {
  const test::TempDir dir("cli-style");
  LastParams params = LastParams::for_eu_size(40, FootSide::Right);
  params.target_triangles = 30000;
  params.random_pose = true;
  params.seed = 11;
  write_mesh(dir / "last.stl", generate_last(params).mesh);
  const test::CommandRun run =
      test::run_lastcut("style pieces '" + kDerby.string() + "' '" + (dir / "last.stl").string() + "' -o '" + (dir / "out").string() + "'", dir);
  ASSERT_EQ(run.exit_code, 0) << run.all();
  EXPECT_NE(run.out.find("4 pieces of style derby"), std::string::npos) << run.out;

  const nlohmann::json report = nlohmann::json::parse(test::read_text(dir / "out" / "pieces.json"));
  ASSERT_EQ(report["pieces"].size(), 4u);
  const double upper = report["upper_area_3d_mm2"], pieces = report["pieces_area_3d_mm2"];
  EXPECT_NEAR(pieces, upper, 1e-3 * upper);
  for (const auto& piece : report["pieces"]) {
    const std::string name = piece["name"];
    EXPECT_EQ(piece["flipped_triangles"], 0) << name;
    EXPECT_EQ(piece["material"], "upper leather") << name;
    const Mold mold = read_mold_dxf(dir / "out" / piece["file"].get<std::string>());
    EXPECT_GT(mold.outline.points.size(), 10u) << name;
    EXPECT_TRUE(fs::exists(dir / "out" / (fs::path(piece["file"].get<std::string>()).stem().string() + ".svg"))) << name;
    // Every piece has its lasting margin: the feather line is among its edges with 18 mm.
    bool lasting = false;
    for (const auto& edge : piece["edges"]) lasting = lasting || (edge["on"] == "feather line" && edge["allowance_mm"] == 18.0);
    EXPECT_TRUE(lasting) << name;
  }
}

// `lastcut pieces` writes what a pattern room exchanges: every piece in one DXF-AAMA file, which our
// reader and, independently, ezdxf (Debian's python3-ezdxf, under Debian's own interpreter) read and
// audit clean; the notches, grain line and seam lengths in pieces.json agree with it.
TEST(CliStylePieces, PiecesCommandWritesDxfAamaAndTheSeams) {
  const test::TempDir dir("cli-pieces");
  LastParams params = LastParams::for_eu_size(41, FootSide::Left);
  params.target_triangles = 30000;
  write_mesh(dir / "last.stl", generate_last(params).mesh);
  const test::CommandRun run = test::run_lastcut(
      "pieces '" + (dir / "last.stl").string() + "' --style '" + kDerby.string() + "' -o '" + (dir / "out").string() + "' --size 41 --side left", dir);
  ASSERT_EQ(run.exit_code, 0) << run.all();
  const nlohmann::json report = nlohmann::json::parse(test::read_text(dir / "out" / "pieces.json"));
  ASSERT_EQ(report["pieces"].size(), 4u);
  ASSERT_EQ(report["seams"].size(), 4u);
  for (const auto& seam : report["seams"]) EXPECT_LE(std::abs(seam["difference_mm"].get<double>()), 0.5) << seam.dump();

  const fs::path aama = dir / "out" / "aama" / "derby-41-left.dxf";
  const std::vector<PatternPiece> patterns = read_aama_dxf(aama);
  ASSERT_EQ(patterns.size(), 4u);
  for (std::size_t p = 0; p < patterns.size(); ++p) {
    const PatternPiece& pattern = patterns[p];
    const auto& piece = report["pieces"][p];
    EXPECT_EQ(pattern.name, piece["name"]);
    EXPECT_EQ(pattern.size, "41");
    EXPECT_EQ(pattern.style, "derby");
    EXPECT_EQ(pattern.annotation, "left");
    EXPECT_EQ(pattern.category, "upper leather");
    EXPECT_EQ(pattern.notches.size(), piece["notches"].size()) << pattern.name;
    ASSERT_TRUE(pattern.grain_line_mm) << pattern.name;
    EXPECT_LT(((*pattern.grain_line_mm)[0] - Point2(piece["grain_line_mm"][0][0], piece["grain_line_mm"][0][1])).norm(), 1e-6);
    EXPECT_EQ(pattern.internal_lines_mm.size(), 1u) << pattern.name;  // the net line
    EXPECT_GE(pattern.sew_lines_mm.size(), 1u) << pattern.name;      // every derby piece is sewn to another
    for (std::size_t n = 0; n < pattern.notches.size(); ++n)
      EXPECT_LT((pattern.notches[n].at_mm - Point2(piece["notches"][n]["on_cut_line_mm"][0], piece["notches"][n]["on_cut_line_mm"][1])).norm(), 1e-6);
  }
  const int status = test::run_to_exit({"/usr/bin/python3", std::string(LASTCUT_SOURCE_DIR) + "/tests/pattern/aama_ezdxf_report.py",
                                        aama.string(), (dir / "ezdxf.json").string()},
                                       dir / "ezdxf.log", 120.0);
  ASSERT_EQ(status, 0) << test::read_text(dir / "ezdxf.log");
  const nlohmann::json ezdxf = nlohmann::json::parse(test::read_text(dir / "ezdxf.json"));
  EXPECT_TRUE(ezdxf["audit_errors"].empty()) << ezdxf["audit_errors"].dump();
  EXPECT_TRUE(ezdxf["audit_fixes"].empty()) << ezdxf["audit_fixes"].dump();
  ASSERT_EQ(ezdxf["pieces"].size(), 4u);
  for (std::size_t p = 0; p < patterns.size(); ++p) {
    EXPECT_EQ(ezdxf["pieces"][p]["closed_cut_lines"], nlohmann::json::array({patterns[p].cut_line_mm.size()}));
    EXPECT_EQ(ezdxf["pieces"][p]["notch_points"].size(), patterns[p].notches.size());
    EXPECT_EQ(ezdxf["pieces"][p]["grain_lines"].size(), 1u);
  }
}

// Lasts where earlier versions failed, both feet (the derby is drawn on a right last): EU 38 right, where
// the closed counter line's two ends met end to end and let the counter and a quarter touch; EU 36 and
// 47 at the ends of the size range; 20k triangles, posed.
TEST(CliStylePieces, DerbyOnSizesAndBothFeet) {
  const test::TempDir dir("cli-style-sizes");
  for (const auto& [size, side] : std::vector<std::pair<int, FootSide>>{{38, FootSide::Right}, {36, FootSide::Left}, {47, FootSide::Left}}) {
    LastParams params = LastParams::for_eu_size(size, side);
    params.target_triangles = 20000;
    params.random_pose = true;
    params.seed = static_cast<std::uint64_t>(size);
    write_mesh(dir / "last.stl", generate_last(params).mesh);
    const test::CommandRun run = test::run_lastcut("style pieces '" + kDerby.string() + "' '" + (dir / "last.stl").string() + "' -o '" +
                                                       (dir / "out").string() + "' --side " + (side == FootSide::Left ? "left" : "right"),
                                                   dir);
    EXPECT_EQ(run.exit_code, 0) << size << ": " << run.all();
    EXPECT_NE(run.out.find("4 pieces of style derby"), std::string::npos) << size << ": " << run.out;
  }
}

TEST(CliStylePieces, AStyleWithAMistakeIsRefusedInOneLine) {
  const test::TempDir dir("cli-style-bad");
  fs::create_directories(dir / "style");
  fs::copy_file(kDerby / "lines.obj", dir / "style" / "lines.obj");
  std::string toml = test::read_text(kDerby / "style.toml");
  toml.replace(toml.find("lasting = 18.0"), 14, "lastng = 18.0");
  std::ofstream(dir / "style" / "style.toml") << toml;
  LastParams params = LastParams::for_eu_size(40, FootSide::Right);
  params.target_triangles = 5000;
  write_mesh(dir / "last.stl", generate_last(params).mesh);
  const test::CommandRun run = test::run_lastcut(
      "style pieces '" + (dir / "style").string() + "' '" + (dir / "last.stl").string() + "' -o '" + (dir / "out").string() + "'", dir);
  EXPECT_EQ(run.exit_code, 2) << run.all();
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_TRUE(run.err.starts_with("lastcut: error: ")) << run.err;
  EXPECT_NE(run.err.find("allowances.lastng"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "pieces.json"));
}

}  // namespace
}  // namespace lastcut
