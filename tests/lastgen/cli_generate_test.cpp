// `lastcut generate` end to end: the real binary writes a last that intake reads back with the
// asked size, holes and pose; the same seed gives the same bytes; bad arguments fail with one line.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "engine/mesh/read_mesh.hpp"
#include "tests/support/lastcut_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

using CommandResult = test::CommandRun;

class CliGenerate : public ::testing::Test {
 protected:

  static std::string slurp(const std::filesystem::path& path) { return test::read_text(path); }

  CommandResult run(const std::string& arguments) const {
    return test::run_lastcut("generate " + arguments, dir_);
  }

  const test::TempDir dir_{"cli-generate"};
};

TEST_F(CliGenerate, WritesTheAskedLastAndTheSameBytesForTheSameSeed) {
  const std::string file = (dir_ / "a.obj").string();
  const CommandResult first = run("-o '" + file + "' --size 40 --side right --triangles 3000 --noise 0.1 --holes 2 --seed 5");
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.out.find("wrote"), std::string::npos) << first.out;
  const MeshIntake intake = read_mesh(file);
  EXPECT_NEAR(intake.mesh.triangle_count(), 3000, 80);  // minus the two holes
  EXPECT_EQ(intake.report.boundary_loops, 2);
  EXPECT_NEAR(bounding_box_size(intake.mesh).x(), 40 * 20.0 / 3.0, 3.0);
  const std::string bytes = slurp(file);
  ASSERT_EQ(run("-o '" + file + "' --size 40 --side right --triangles 3000 --noise 0.1 --holes 2 --seed 5").exit_code, 0);
  EXPECT_EQ(slurp(file), bytes);
}

TEST_F(CliGenerate, RandomPoseIsWrittenAndUndoesToTheCanonicalFrame) {
  const std::string file = (dir_ / "posed.stl").string(), pose = (dir_ / "pose.json").string();
  const CommandResult result = run("-o '" + file + "' --size 42 --triangles 3000 --random-pose --seed 9 --pose-out '" + pose + "'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json document = nlohmann::json::parse(slurp(pose));
  Eigen::Matrix4d matrix;
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) matrix(row, col) = document["canonical_to_scan"][row][col].get<double>();
  EXPECT_TRUE(matrix.row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1)));
  const Eigen::Affine3d to_scan(matrix);
  EXPECT_TRUE((to_scan.linear().transpose() * to_scan.linear()).isApprox(Eigen::Matrix3d::Identity(), 1e-9));
  TriMesh mesh = read_mesh(file).mesh;
  const Eigen::Affine3d back = to_scan.inverse();
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) mesh.V.row(v) = (back * Eigen::Vector3d(mesh.V.row(v).transpose())).transpose();
  EXPECT_NEAR(mesh.V.col(2).minCoeff(), 0.0, 0.01);  // float STL precision
  EXPECT_NEAR(bounding_box_size(mesh).x(), 280.0, 3.0);
}

TEST_F(CliGenerate, StitchingSeamsAddTheirZipperTrianglesAndSayItsASeamedScan) {
  const std::string plain = (dir_ / "plain.stl").string(), seamed = (dir_ / "seamed.stl").string();
  ASSERT_EQ(run("-o '" + plain + "' --size 41 --side right --triangles 3000 --seed 4").exit_code, 0);
  const CommandResult result = run("-o '" + seamed + "' --size 41 --side right --triangles 3000 --seed 4 --seams 2 --seam-step 0.2");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find(", stitching seams"), std::string::npos) << result.out;
  const MeshIntake seamed_intake = read_mesh(seamed);
  EXPECT_GT(seamed_intake.mesh.triangle_count(), read_mesh(plain).mesh.triangle_count() + 50);
  EXPECT_EQ(seamed_intake.report.boundary_loops, 0) << "one closed sheet";
  EXPECT_NE(run("-o '" + seamed + "' --seams 9").exit_code, 0);
}

TEST_F(CliGenerate, BadArgumentsFailWithOneLine) {
  CommandResult result = run("-o '" + (dir_ / "x.stl").string() + "' --size 30");
  EXPECT_NE(result.exit_code, 0);
  EXPECT_NE(result.err.find("size"), std::string::npos) << result.err;
  result = run("-o '" + (dir_ / "x.xyz").string() + "'");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("output must end in .stl, .obj, .ply or .off"), std::string::npos) << result.err;
  result = run("-o '" + (dir_ / "missing" / "x.stl").string() + "' --triangles 2000");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("cannot write"), std::string::npos) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  result = run("--size 42");
  EXPECT_NE(result.exit_code, 0);
}

}  // namespace
}  // namespace lastcut
