// A style authored the way pattern makers work (issue 34, point 1), through the real binary:
// `lastcut style new` on the generated EU 42 right last (the shipped derby's reference) writes the
// forme, the scan's copy and a style.toml template; the forme's layers are read back with the project's
// DXF reader and, when Debian's python3-ezdxf is installed, read and audited by ezdxf. Then the derby is
// drawn on that forme.dxf as a pattern maker would (tests/support/derby_forme.hpp) and `lastcut style
// pieces` must cut the same four pieces from another last as the shipped, 3D-drawn derby, each piece's
// 3D area within 0.5 %. A [[piece]] without a text and a fresh template are refused in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "daemon/config/style_folder.hpp"
#include "engine/core/dxf_reader.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "tests/support/derby_forme.hpp"
#include "tests/support/lastcut_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

const fs::path kDerby = fs::path(LASTCUT_SOURCE_DIR) / "config" / "styles" / "derby";
// Debian's interpreter: python3-ezdxf installs for it, not for another python3 first on PATH.
const char* const kDebianPython = "/usr/bin/python3";

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

// How the derby's style.toml says its lines and seams are sewn: the rules a pattern maker adds to the template.
constexpr const char* kDerbyRules = R"(
[[line]]
name = "vamp"
under = "vamp"
[[line]]
name = "counter"
under = "medial quarter"
[[line]]
name = "counter"
under = "lateral quarter"
[[seam_cut]]
seam = "front"
from_line = "vamp"
[[seam_cut]]
seam = "back"
from_line = "counter"
[[piece]]
name = "vamp"
material = "upper leather"
quantity = 1
)";

class CliStyleForme : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir("cli-style-forme");
    Result<daemon::StyleFolder> derby = daemon::read_style_folder(kDerby);
    ASSERT_TRUE(derby) << derby.error();
    write_mesh(*dir_ / "reference42.stl", generate_last(*derby->generated_reference).mesh);
    new_run_ = new test::CommandRun(
        test::run_lastcut("style new " + quoted(*dir_ / "reference42.stl") + " -o " + quoted(*dir_ / "new") + " --side right", *dir_));
  }
  static void TearDownTestSuite() {
    delete new_run_;
    delete dir_;
  }
  static fs::path style_dir() { return *dir_ / "new"; }

  static inline test::TempDir* dir_ = nullptr;
  static inline test::CommandRun* new_run_ = nullptr;
};

TEST_F(CliStyleForme, StyleNewWritesTheFormeTheScanAndATemplate) {
  ASSERT_EQ(new_run_->exit_code, 0) << new_run_->all();
  EXPECT_NE(new_run_->out.find("next:"), std::string::npos) << new_run_->out;
  EXPECT_NE(new_run_->out.find("LINE-<name>"), std::string::npos) << new_run_->out;
  EXPECT_EQ(test::read_text(style_dir() / "reference.stl"), test::read_text(*dir_ / "reference42.stl"));

  const DxfDrawing forme = read_dxf_drawing(style_dir() / "forme.dxf");
  EXPECT_EQ(forme.insunits, 4);  // mm
  for (const char* layer : {"0", "LATERAL", "MEDIAL", "FEATHER", "TOP", "CENTRE", "LANDMARKS", "PIECES", "LINE-example"})
    EXPECT_NE(std::find(forme.layers.begin(), forme.layers.end(), layer), forme.layers.end()) << layer;
  std::map<std::string, int> polylines, closed, points, texts;
  for (const DxfPolyline& polyline : forme.polylines) ++polylines[polyline.layer], closed[polyline.layer] += polyline.closed;
  for (const DxfPoint& point : forme.points) ++points[point.layer];
  for (const DxfText& text : forme.texts) ++texts[text.layer];
  EXPECT_EQ(polylines, (std::map<std::string, int>{{"LATERAL", 1}, {"MEDIAL", 1}, {"FEATHER", 2}, {"TOP", 2}, {"CENTRE", 4}}));
  EXPECT_EQ(closed["LATERAL"] + closed["MEDIAL"], 2);
  EXPECT_EQ(points["LANDMARKS"], 8);
  EXPECT_EQ(texts["LANDMARKS"], 8);
  EXPECT_GE(texts["0"], 1);
  EXPECT_EQ(texts["PIECES"], 0);

  // The template is a valid style.toml; what it lacks is the drawing: refused in one line, naming the forme.
  const test::CommandRun run = test::run_lastcut("style pieces " + quoted(style_dir()) + " " + quoted(*dir_ / "reference42.stl") + " -o " +
                                                     quoted(*dir_ / "out-template"),
                                                 *dir_);
  EXPECT_EQ(run.exit_code, 2) << run.all();
  EXPECT_EQ(run.err, "lastcut: error: " + (style_dir() / "style.toml").string() + ": " + (style_dir() / "forme.dxf").string() +
                         ": no piece text: write each piece's name as a TEXT on layer PIECES, inside the piece\n");

  // Run again into the same folder: the drawing is never overwritten.
  const test::CommandRun again = test::run_lastcut("style new " + quoted(*dir_ / "reference42.stl") + " -o " + quoted(style_dir()), *dir_);
  EXPECT_EQ(again.exit_code, 2) << again.all();
  EXPECT_NE(again.err.find("exists"), std::string::npos) << again.err;
}

TEST_F(CliStyleForme, EzdxfReadsAndAuditsTheForme) {
  ASSERT_EQ(new_run_->exit_code, 0) << new_run_->all();
  if (std::system((std::string(kDebianPython) + " -c 'import ezdxf' 2>/dev/null").c_str()) != 0)
    GTEST_SKIP() << "python3-ezdxf is not installed";
  const fs::path script = *dir_ / "audit.py";
  std::ofstream(script) << "import sys, ezdxf\n"
                           "doc = ezdxf.readfile(sys.argv[1])\n"
                           "auditor = doc.audit()\n"
                           "print(len(auditor.errors), len(list(doc.modelspace())))\n"
                           "print(' '.join(sorted(layer.dxf.name for layer in doc.layers)))\n";
  const fs::path out = *dir_ / "audit.txt";
  ASSERT_EQ(std::system((std::string(kDebianPython) + " " + quoted(script) + " " + quoted(style_dir() / "forme.dxf") + " > " + quoted(out)).c_str()), 0);
  std::ifstream report(out);
  int errors = -1, entities = 0;
  report >> errors >> entities;
  std::string layers;
  std::getline(report >> std::ws, layers);
  EXPECT_EQ(errors, 0);
  EXPECT_EQ(entities, 2 + 8 + 16 + 4);  // outlines, edges, landmark points and names, the note on layer 0
  for (const char* layer : {"LATERAL", "MEDIAL", "FEATHER", "TOP", "CENTRE", "LANDMARKS", "PIECES", "LINE-example"})
    EXPECT_NE(layers.find(layer), std::string::npos) << layers;
}

TEST_F(CliStyleForme, DerbyDrawnOnTheFormeCutsTheDerbysPieces) {
  ASSERT_EQ(new_run_->exit_code, 0) << new_run_->all();
  // The derby drawn on the forme `style new` wrote: the layout is recomputed here from the same scan
  // and must be the one in the file (a style is lifted by recomputing it).
  const Result<daemon::StyleFolder> derby = daemon::read_style_folder(kDerby);
  ASSERT_TRUE(derby) << derby.error();
  ScanOptions options;
  options.side = FootSide::Right;
  const ScanResult reference = scan_to_molds(style_dir() / "reference.stl", options);
  const FormeLayout layout = forme_layout(reference);
  const DxfDrawing written = read_dxf_drawing(style_dir() / "forme.dxf");
  for (const DxfPolyline& outline : written.polylines)
    if (outline.layer == "LATERAL" || outline.layer == "MEDIAL") {
      const std::vector<Point2> expected = layout.halves[outline.layer == "MEDIAL" ? 0 : 1].outline();
      ASSERT_EQ(outline.vertices.size(), expected.size()) << outline.layer;
      double worst = 0;
      for (std::size_t i = 0; i < expected.size(); ++i) worst = std::max(worst, (outline.vertices[i].point - expected[i]).norm());
      EXPECT_LT(worst, 1e-5) << outline.layer;
    }
  const StyleTransfer identity(reference, reference);
  std::vector<test::DrawnPolyline> lines;
  for (const StyleLine& line : derby->style.lines)
    for (const test::DrawnPolyline& drawn : test::line_on_forme(identity, layout, line)) lines.push_back(drawn);
  std::vector<test::DrawnText> texts;
  for (const StylePiece& piece : derby->style.pieces) texts.push_back({piece.name, test::point_on_forme(identity, layout, piece.label_mm)});

  const fs::path drawn = *dir_ / "drawn";
  fs::create_directories(drawn);
  fs::copy_file(style_dir() / "reference.stl", drawn / "reference.stl");
  std::ofstream(drawn / "forme.dxf") << test::with_entities_of(test::read_text(style_dir() / "forme.dxf"), test::drawing_dxf(lines, texts));
  std::ofstream(drawn / "style.toml") << test::read_text(style_dir() / "style.toml") << kDerbyRules;

  LastParams params = LastParams::for_eu_size(40, FootSide::Right);
  params.target_triangles = 30000;
  params.random_pose = true;
  params.seed = 11;
  write_mesh(*dir_ / "last40.stl", generate_last(params).mesh);
  std::map<std::string, std::map<std::string, double>> areas;  // style -> piece -> 3D area
  for (const auto& [name, folder] : {std::pair{"shipped", kDerby}, std::pair{"forme", drawn}}) {
    const test::CommandRun run =
        test::run_lastcut("style pieces " + quoted(folder) + " " + quoted(*dir_ / "last40.stl") + " -o " + quoted(*dir_ / name), *dir_);
    ASSERT_EQ(run.exit_code, 0) << name << ": " << run.all();
    const nlohmann::json report = nlohmann::json::parse(test::read_text(*dir_ / name / "pieces.json"));
    for (const auto& piece : report["pieces"]) {
      areas[name][piece["name"]] = piece["area_3d_mm2"];
      EXPECT_EQ(piece["flipped_triangles"], 0) << name << " " << piece["name"];
    }
  }
  ASSERT_EQ(areas["forme"].size(), 4u);
  for (const auto& [piece, area] : areas["shipped"]) {
    ASSERT_TRUE(areas["forme"].contains(piece)) << piece;
    const double forme_area = areas["forme"][piece];
    std::printf("%-16s shipped %9.2f mm2  drawn on the forme %9.2f mm2  %+.4f %%\n", piece.c_str(), area, forme_area,
                100 * (forme_area - area) / area);
    EXPECT_NEAR(forme_area, area, 0.005 * area) << piece;
  }

  // A [[piece]] the drawing does not name is refused in one line, before the new last is read.
  std::ofstream(drawn / "style.toml", std::ios::app) << "[[piece]]\nname = \"tongue\"\n";
  const test::CommandRun run =
      test::run_lastcut("style pieces " + quoted(drawn) + " " + quoted(*dir_ / "last40.stl") + " -o " + quoted(*dir_ / "tongue"), *dir_);
  EXPECT_EQ(run.exit_code, 1) << run.all();
  EXPECT_EQ(run.err, "lastcut: error: piece tongue of style.toml has no text on layer PIECES of " + (drawn / "forme.dxf").string() +
                         ": write its name inside it\n");
}

}  // namespace
}  // namespace lastcut
