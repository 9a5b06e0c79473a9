// `lastcut style transfer` as a pattern maker runs it: the real binary, a line drawn on a generated EU 42
// right last and the same last scaled by 1.1. The line is the last's plane section at x = 60 mm, all the
// way round: over the sole, up both sides and across the top opening. The oracle is the geometry, not
// the transfer: every point written lies on the scaled section. The parts over the sole and the opening
// are left out, so the line comes back in two parts (one per side), neither with a chord across. A lines
// file with a face, a line nowhere on the upper and a misspelt side are refused in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "engine/style/style_lines_obj.hpp"
#include "tests/support/lastcut_cli.hpp"
#include "tests/support/style_line_geometry.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

constexpr double kScale = 1.1;

class CliStyleTransfer : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    LastParams params = LastParams::for_eu_size(42, FootSide::Right);
    params.target_triangles = 20000;
    TriMesh last = generate_last(params).mesh;
    write_mesh(dir_ / "reference.stl", last);
    section_ = new test::Polyline(test::plane_section_through(last, {1, 0, 0}, {60, 0, 0}));
    last.V *= kScale;
    write_mesh(dir_ / "scaled.stl", last);
  }
  static void TearDownTestSuite() { delete section_; }
  // `lastcut style transfer` from the reference onto the scaled last, with `extra` options.
  static test::CommandRun transfer(const fs::path& lines, const std::string& extra = "") {
    return test::run_lastcut("style transfer '" + (dir_ / "reference.stl").string() + "' '" + lines.string() + "' '" +
                                 (dir_ / "scaled.stl").string() + "' -o '" + (dir_ / "out.obj").string() + "'" + extra,
                             dir_);
  }
  static inline test::TempDir dir_{"cli-style-transfer"};
  static inline test::Polyline* section_ = nullptr;
};

TEST_F(CliStyleTransfer, PlaneSectionOntoTheScaledLastStaysOnItsSection) {
  ASSERT_GT(section_->size(), 100u);
  write_style_lines_obj(dir_ / "lines.obj", {{"cross line", *section_}});
  const test::CommandRun run = transfer(dir_ / "lines.obj", " --side right --reference-side right");
  ASSERT_EQ(run.exit_code, 0) << run.all();
  EXPECT_TRUE(run.out.starts_with("cross line ")) << run.out;
  EXPECT_NE(run.out.find("in 2 parts"), std::string::npos) << run.out;

  const std::vector<StyleLine> lines = read_style_lines_obj(dir_ / "out.obj");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].name, "cross line");
  EXPECT_EQ(lines[1].name, "cross line (2)");
  test::Polyline truth;
  for (const Eigen::Vector3d& p : *section_) truth.push_back(kScale * p);
  double worst_mm = 0, longest_step_mm = 0;
  std::size_t points = 0;
  for (const StyleLine& line : lines) {
    for (const Eigen::Vector3d& p : line.points_mm) worst_mm = std::max(worst_mm, test::distance_to_polyline(p, truth));
    for (std::size_t i = 1; i < line.points_mm.size(); ++i)
      longest_step_mm = std::max(longest_step_mm, (line.points_mm[i] - line.points_mm[i - 1]).norm());
    points += line.points_mm.size();
  }
  std::printf("%zu points in 2 parts, worst %.3f mm off the scaled section, longest step %.2f mm\n", points, worst_mm,
              longest_step_mm);
  EXPECT_GT(points, 150u);
  EXPECT_LE(worst_mm, 1.2);
  EXPECT_LE(longest_step_mm, 3.0);  // resampled at 1 mm on the reference: no chord over the sole or the opening
}

TEST_F(CliStyleTransfer, ALinesFileWithAFaceIsRefusedInOneLine) {
  std::ofstream(dir_ / "face.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  fs::remove(dir_ / "out.obj");
  const test::CommandRun run = transfer(dir_ / "face.obj");
  EXPECT_NE(run.exit_code, 0) << run.all();
  EXPECT_FALSE(run.crashed);
  EXPECT_EQ(run.err, "lastcut: error: face.obj line 4: a face: style lines are polylines (l records), not a surface\n");
  EXPECT_FALSE(fs::exists(dir_ / "out.obj"));
}

TEST_F(CliStyleTransfer, ALineOffTheUpperIsRefusedByName) {
  std::ofstream(dir_ / "off.obj") << "v 100 0 -40\nv 150 0 -40\no under the sole\nl 1 2\n";
  fs::remove(dir_ / "out.obj");
  const test::CommandRun run = transfer(dir_ / "off.obj");
  EXPECT_EQ(run.exit_code, 1) << run.all();
  EXPECT_EQ(run.err, "lastcut: error: the line \"under the sole\" does not lie on the reference last's upper\n");
  EXPECT_FALSE(fs::exists(dir_ / "out.obj"));
}

TEST_F(CliStyleTransfer, AMisspeltSideIsRefusedInOneLine) {
  write_style_lines_obj(dir_ / "lines.obj", {{"cross line", *section_}});
  const test::CommandRun run = transfer(dir_ / "lines.obj", " --reference-side rigth");
  EXPECT_EQ(run.exit_code, 2) << run.all();
  EXPECT_EQ(run.err, "lastcut: error: --reference-side must be left or right, not \"rigth\"\n");
}

}  // namespace
}  // namespace lastcut
