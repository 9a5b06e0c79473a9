// Style lines as OBJ polylines (engine/style/style_lines_obj.hpp): what is written is read back, OBJ's
// relative indices and names work, and every bad file is refused in exactly one line.
#include <gtest/gtest.h>

#include <fstream>

#include "engine/core/engine_error.hpp"
#include "engine/style/style_lines_obj.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

class StyleLinesObj : public ::testing::Test {
 protected:
  std::filesystem::path write(const std::string& text) {
    const std::filesystem::path path = dir_ / "lines.obj";
    std::ofstream(path) << text;
    return path;
  }
  std::string refusal(const std::string& text) {
    try {
      read_style_lines_obj(write(text));
    } catch (const EngineError& error) {
      return error.what();
    }
    return "(read without error)";
  }
  test::TempDir dir_{"style-lines"};
};

TEST_F(StyleLinesObj, WrittenLinesReadBack) {
  const std::vector<StyleLine> lines = {{"vamp", {{0, 0, 0}, {1.5, 2.25, -3}, {4, 5, 6}}}, {"counter line", {{7, 8, 9}, {10, 11, 12}}}};
  write_style_lines_obj(dir_ / "out.obj", lines);
  const std::vector<StyleLine> back = read_style_lines_obj(dir_ / "out.obj");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].name, "vamp");
  EXPECT_EQ(back[1].name, "counter line");
  ASSERT_EQ(back[0].points_mm.size(), 3u);
  EXPECT_TRUE(back[0].points_mm[1].isApprox(Eigen::Vector3d(1.5, 2.25, -3)));
  EXPECT_TRUE(back[1].points_mm[1].isApprox(Eigen::Vector3d(10, 11, 12)));
}

TEST_F(StyleLinesObj, RelativeIndicesGroupsAndUnnamedLines) {
  const std::vector<StyleLine> lines = read_style_lines_obj(write(
      "# from CAD\r\nv 0 0 0\nv 1 0 0\nv 2 0 0\nl 1 2\ng quarter\nvn 0 0 1\nv 3 0 0\nl -2 -1\n"));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].name, "line 1");
  EXPECT_EQ(lines[1].name, "quarter");
  EXPECT_DOUBLE_EQ(lines[1].points_mm[0].x(), 2);
  EXPECT_DOUBLE_EQ(lines[1].points_mm[1].x(), 3);
}

TEST_F(StyleLinesObj, NamesLoseTrailingBlanksAndABareObjectEndsTheName) {
  const std::vector<StyleLine> lines = read_style_lines_obj(write("v 0 0 0\nv 1 0 0\no vamp \t\nl 1 2\no\nl 2 1\n"));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].name, "vamp");
  EXPECT_EQ(lines[1].name, "line 2");
}

TEST_F(StyleLinesObj, BadFilesAreRefusedInOneLine) {
  EXPECT_EQ(refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "lines.obj line 4: a face: style lines are polylines (l records), not a surface");
  EXPECT_EQ(refusal("v 0 0 x\n"), "lines.obj line 1: 'x' is not a number");
  EXPECT_EQ(refusal("v 0 0\n"), "lines.obj line 1: a vertex needs three coordinates");
  EXPECT_EQ(refusal("v 0 0 0\nv 1 0 0\nl 1 3\n"), "lines.obj line 3: vertex index 3 is not one of the 2 vertices so far");
  // Beyond any integer: refused before it is made one (the style_lines fuzz target's regression-huge-index).
  EXPECT_EQ(refusal("v 0 0 0\nv 1 0 0\nl 1 -1e300\n"), "lines.obj line 3: vertex index -1e300 is not one of the 2 vertices so far");
  EXPECT_EQ(refusal("v 0 0 0\nl 1\n"), "lines.obj line 2: a line needs at least two points");
  EXPECT_EQ(refusal("v 0 0 0\nv 1 0 0\no a\nl 1 2\no a\nl 2 1\n"), "lines.obj line 6: a second line named a: each line needs its own name");
  EXPECT_EQ(refusal("v 0 0 0\n"), "lines.obj: no lines (l records) in the file");
  try {
    read_style_lines_obj(dir_.path() / "missing.obj");
    FAIL();
  } catch (const EngineError& error) {
    EXPECT_EQ(std::string(error.what()), "cannot read style lines " + (dir_.path() / "missing.obj").string());
  }
}

}  // namespace
}  // namespace lastcut
