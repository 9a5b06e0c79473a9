// `lastcut subdivide` end to end with the real binary: a quad OBJ in, the n x n quad OBJ out, read
// back with its exact counts; bad input fails with one line on stderr.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/subdiv/quad_obj.hpp"
#include "engine/subdiv/sample_surface.hpp"
#include "tests/subdiv/quad_test_meshes.hpp"
#include "tests/support/lastcut_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

using CommandResult = test::CommandRun;

class CliSubdivide : public ::testing::Test {
 protected:

  static std::string slurp(const std::filesystem::path& path) { return test::read_text(path); }
  CommandResult run(const std::string& arguments) const {
    return test::run_lastcut("subdivide " + arguments, dir_);
  }
  static int line_count(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

  const test::TempDir dir_{"cli-subdivide"};
};

TEST_F(CliSubdivide, WritesTheSampledQuadMesh) {
  const QuadMesh control = test::cube_sphere(2, 30.0);
  const auto input = dir_ / "cube.obj", output = dir_ / "smooth.obj";
  write_quad_obj(input, control);
  const CommandResult result = run("'" + input.string() + "' --n 3 -o '" + output.string() + "'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("24 control quads at n = 3 -> 216 quads"), std::string::npos) << result.out;
  const QuadMesh written = read_quad_obj(output);
  EXPECT_EQ(written.quad_count(), 24 * 9);
  EXPECT_EQ(written.vertex_count(), 26 + 48 * 2 + 24 * 4);
  // The same surface as the library computes from the file it read (6 decimals in the file).
  const SubdividedSurface expected = subdivide_bezier(read_quad_obj(input), 3);
  EXPECT_EQ(written.Q, expected.quads.Q);
  EXPECT_LT((written.V - expected.quads.V).cwiseAbs().maxCoeff(), 1e-6);
  // --even: the same connectivity, samples moved only near the eight valence-3 corners.
  ASSERT_EQ(run("'" + input.string() + "' --n 3 --even -o '" + output.string() + "'").exit_code, 0);
  const QuadMesh even = read_quad_obj(output);
  EXPECT_EQ(even.Q, expected.quads.Q);
  const SubdividedSurface expected_even = subdivide_bezier(read_quad_obj(input), 3, SampleSpread::EvenAtExtraordinary);
  EXPECT_LT((even.V - expected_even.quads.V).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_GT((even.V - written.V).cwiseAbs().maxCoeff(), 0.1);
}

TEST_F(CliSubdivide, BadInputFailsWithOneLine) {
  const auto triangles = dir_ / "tri.obj";
  std::ofstream(triangles) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  CommandResult result = run("'" + triangles.string() + "' --n 3 -o '" + (dir_ / "x.obj").string() + "'");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("a face with 3 corners"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "x.obj"));

  const auto cube = dir_ / "cube.obj";
  write_quad_obj(cube, test::cube_sphere(1, 10.0));
  result = run("'" + cube.string() + "' --n 0 -o '" + (dir_ / "x.obj").string() + "'");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("detail n = 0 is out of range"), std::string::npos) << result.err;
}

TEST_F(CliSubdivide, GenerateBuildsTheLastThroughTheBezierSurfaceWhenAsked) {
  const auto file = dir_ / "last.obj";
  const auto generate = [&] {
    const std::string command = std::string("'") + LASTCUT_BINARY_DIR + "/bin/lastcut' generate -o '" + file.string() +
                                "' --triangles 5000 --surface bezier --noise 0.1 >'" + (dir_ / "out.txt").string() + "' 2>&1";
    return std::system(command.c_str());
  };
  ASSERT_EQ(generate(), 0) << slurp(dir_ / "out.txt");
  const std::string text = slurp(file);
  int faces = 0;
  for (size_t at = text.find("\nf "); at != std::string::npos; at = text.find("\nf ", at + 1)) ++faces;
  EXPECT_NEAR(faces, 5000, 300);
  ASSERT_EQ(generate(), 0);
  EXPECT_EQ(slurp(file), text);  // deterministic
}

}  // namespace
}  // namespace lastcut
