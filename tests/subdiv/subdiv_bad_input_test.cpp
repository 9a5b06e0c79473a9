// Bad control meshes and details are refused with one line an operator can act on.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "engine/core/engine_error.hpp"
#include "engine/subdiv/quad_obj.hpp"
#include "engine/subdiv/sample_surface.hpp"
#include "tests/subdiv/quad_test_meshes.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

// The test process's own folder, removed at its exit.
const test::TempDir& folder() {
  static const test::TempDir dir("subdiv-bad-input");
  return dir;
}

std::filesystem::path write_text(const std::string& name, const std::string& text) {
  const std::filesystem::path path = folder() / name;
  std::ofstream(path) << text;
  return path;
}

// Runs `action`, expects an EngineError whose one-line message contains `expected`.
template <typename Action>
void expect_refusal(Action action, const std::string& expected) {
  try {
    action();
    ADD_FAILURE() << "accepted; expected a refusal containing '" << expected << "'";
  } catch (const EngineError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(expected), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

const char* kTwoQuads = "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\n";

TEST(SubdivBadInput, TrianglesInTheObjAreRefused) {
  const auto path = write_text("tri.obj", std::string(kTwoQuads) + "f 1 2 5 4\nf 2 3 6\n");
  expect_refusal([&] { read_quad_obj(path); }, "line 8: a face with 3 corners; subdivide needs a quad mesh");
}

TEST(SubdivBadInput, BadNumbersAndIndicesAreRefused) {
  expect_refusal([&] { read_quad_obj(write_text("nan.obj", "v 0 nan 0\n")); }, "line 1: 'nan' is not a finite coordinate");
  expect_refusal([&] { read_quad_obj(write_text("idx.obj", std::string(kTwoQuads) + "f 1 2 9 4\n")); },
                 "vertex 9 does not exist (6 vertices so far)");
  expect_refusal([&] { read_quad_obj(write_text("zero.obj", std::string(kTwoQuads) + "f 0 1 2 3\n")); }, "'0' is not a vertex index");
  expect_refusal([&] { read_quad_obj(write_text("empty.obj", "# nothing\nv 1 2 3\n")); }, "has no quads");
  expect_refusal([&] { read_quad_obj(folder() / "missing.obj"); }, "cannot read");
}

TEST(SubdivBadInput, ObjFormsOfCornersAreRead) {
  const QuadMesh mesh = read_quad_obj(write_text("forms.obj", std::string(kTwoQuads) + "vt 0 0\nf 1/1 2/1/1 5//1 4\nf -5 -4 -1 -2\n"));
  ASSERT_EQ(mesh.quad_count(), 2);
  EXPECT_EQ(mesh.Q.row(0), Eigen::RowVector4i(0, 1, 4, 3));
  EXPECT_EQ(mesh.Q.row(1), Eigen::RowVector4i(1, 2, 5, 4));
}

TEST(SubdivBadInput, DetailOutOfRangeIsRefused) {
  const QuadMesh grid = test::height_grid(2, 2, 1);
  expect_refusal([&] { subdivide_bezier(grid, 0); }, "detail n = 0 is out of range 1..1024");
  expect_refusal([&] { subdivide_bezier(grid, 1000000); }, "detail n = 1000000 is out of range 1..1024");
  expect_refusal([&] { subdivide_bezier(test::cube_sphere(20, 10.0), 1000); }, "would make 2400000000 quads from 2400");
}

TEST(SubdivBadInput, NonManifoldMeshesAreRefused) {
  // A third quad on the edge 2-5.
  const std::string fin = std::string(kTwoQuads) + "v 1 0 1\nv 1 1 1\nf 1 2 5 4\nf 2 3 6 5\nf 2 5 8 7\n";
  expect_refusal([&] { subdivide_bezier(read_quad_obj(write_text("fin.obj", fin)), 2); }, "edge 2-5 is used by 3 faces");
  // Two quads touching at one vertex only.
  const std::string bowtie = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 1 0\nv 2 2 0\nv 1 2 0\nf 1 2 3 4\nf 3 5 6 7\n";
  expect_refusal([&] { subdivide_bezier(read_quad_obj(write_text("bowtie.obj", bowtie)), 2); }, "faces at vertex 3 touch only at that vertex");
  // The second quad runs the shared edge the same way as the first.
  const std::string flipped = std::string(kTwoQuads) + "f 1 2 5 4\nf 2 5 6 3\n";
  expect_refusal([&] { subdivide_bezier(read_quad_obj(write_text("flip.obj", flipped)), 2); }, "disagree on their orientation along edge 2-5");
  const std::string repeated = std::string(kTwoQuads) + "f 1 2 2 4\n";
  expect_refusal([&] { subdivide_bezier(read_quad_obj(write_text("rep.obj", repeated)), 2); }, "quad 1 uses vertex 2 twice");
}

}  // namespace
}  // namespace lastcut
