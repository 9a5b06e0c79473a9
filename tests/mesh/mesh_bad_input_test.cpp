// Every class of bad input is refused with an EngineError whose one line says what is wrong.
// The files are made by the test in a temp dir; nothing is mocked.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/core/engine_error.hpp"
#include "engine/mesh/read_mesh.hpp"
#include "test_meshes.hpp"

namespace lastcut {
namespace {

// Runs `action`, expects an EngineError whose message contains `expected` and is one line.
template <typename Action>
void expect_refusal(Action action, const std::string& expected) {
  try {
    action();
    ADD_FAILURE() << "accepted, expected a refusal mentioning '" << expected << "'";
  } catch (const EngineError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(expected), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "message is not one line: " << message;
  }
}

TriMesh small_box() { return test::box_mesh({0, 0, 0}, {250, 90, 120}, 4); }

TEST(MeshBadInput, MissingFile) {
  test::TempDir dir("missing");
  expect_refusal([&] { read_mesh(dir / "nope.stl"); }, "no such file");
}

TEST(MeshBadInput, EmptyFile) {
  test::TempDir dir("empty");
  test::write_text(dir / "empty.stl", "");
  expect_refusal([&] { read_mesh(dir / "empty.stl"); }, "empty file");
}

TEST(MeshBadInput, UnknownExtension) {
  test::TempDir dir("extension");
  test::write_text(dir / "scan.xyz", "1 2 3\n");
  expect_refusal([&] { read_mesh(dir / "scan.xyz"); }, "unknown mesh format '.xyz'");
}

TEST(MeshBadInput, TruncatedBinaryStl) {
  test::TempDir dir("truncated-binary");
  const TriMesh box = small_box();
  test::write_binary_stl_raw(dir / "cut.stl", box);
  std::filesystem::resize_file(dir / "cut.stl", 84 + 50 * 100 + 17);
  expect_refusal([&] { read_mesh(dir / "cut.stl"); }, "truncated binary STL cut.stl: 100 of 192 triangles");
  std::filesystem::resize_file(dir / "cut.stl", 40);
  expect_refusal([&] { read_mesh(dir / "cut.stl"); }, "truncated binary STL");
}

TEST(MeshBadInput, BinaryStlLongerThanItsCount) {
  test::TempDir dir("long-binary");
  test::write_binary_stl_raw(dir / "long.stl", small_box(), 150);
  expect_refusal([&] { read_mesh(dir / "long.stl"); }, "longer than its 150 triangles");
}

TEST(MeshBadInput, TruncatedAsciiStl) {
  test::TempDir dir("truncated-ascii");
  test::write_ascii_stl_raw(dir / "cut.stl", small_box());
  const auto full = std::filesystem::file_size(dir / "cut.stl");
  std::filesystem::resize_file(dir / "cut.stl", full / 2);
  expect_refusal([&] { read_mesh(dir / "cut.stl"); }, "truncated ASCII STL cut.stl: ends inside facet");
}

TEST(MeshBadInput, NanAndInfiniteCoordinates) {
  test::TempDir dir("nan");
  TriMesh box = small_box();
  box.V(5, 1) = std::numeric_limits<double>::quiet_NaN();
  test::write_binary_stl_raw(dir / "nan.stl", box);
  expect_refusal([&] { read_mesh(dir / "nan.stl"); }, "NaN or infinite");
  box = small_box();
  box.V(7, 2) = std::numeric_limits<double>::infinity();
  test::write_binary_stl_raw(dir / "inf.stl", box);
  expect_refusal([&] { read_mesh(dir / "inf.stl"); }, "NaN or infinite");
}

TEST(MeshBadInput, TooManyTrianglesIsRefusedBeforeLoading) {
  test::TempDir dir("cap");
  const TriMesh box = small_box();
  MeshReadOptions options;
  options.max_triangles = 100;
  test::write_binary_stl_raw(dir / "big.stl", box);
  expect_refusal([&] { read_mesh(dir / "big.stl", options); }, "too many triangles in big.stl: 192 (limit 100)");
  test::write_obj_raw(dir / "big.obj", box.V, box.F);
  expect_refusal([&] { read_mesh(dir / "big.obj", options); }, "too many triangles");
  write_mesh(dir / "big.ply", box);
  expect_refusal([&] { read_mesh(dir / "big.ply", options); }, "too many triangles");
  write_mesh(dir / "big.off", box);
  expect_refusal([&] { read_mesh(dir / "big.off", options); }, "too many triangles");
  // A header that claims four billion triangles is refused without reading them.
  test::write_binary_stl_raw(dir / "liar.stl", box, 4000000000L);
  expect_refusal([&] { read_mesh(dir / "liar.stl"); }, "too many triangles");
}

TEST(MeshBadInput, NoTrianglesAtAll) {
  test::TempDir dir("no-faces");
  test::write_text(dir / "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  expect_refusal([&] { read_mesh(dir / "points.obj"); }, "no faces");
  test::write_text(dir / "zero.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  expect_refusal([&] { read_mesh(dir / "zero.off"); }, "no faces");
  test::write_text(dir / "garbage.ply", "not a ply at all\n");
  expect_refusal([&] { read_mesh(dir / "garbage.ply"); }, "not a PLY file");
}

TEST(MeshBadInput, TruncatedOff) {
  test::TempDir dir("truncated-off");
  write_mesh(dir / "box.off", small_box());
  const auto full = std::filesystem::file_size(dir / "box.off");
  std::filesystem::resize_file(dir / "box.off", full - 600);
  expect_refusal([&] { read_mesh(dir / "box.off"); }, "box.off");
}

// OpenMesh reads a short PLY without complaint; intake must name what is missing.
TEST(MeshBadInput, TruncatedBinaryPly) {
  test::TempDir dir("truncated-binary-ply");
  const TriMesh box = small_box();
  const std::string vertices = std::to_string(box.V.rows());
  write_mesh(dir / "box.ply", box);
  const auto full = std::filesystem::file_size(dir / "box.ply");
  const auto face_record_bytes = 1 + 3 * 4;  // uchar count, three int indices
  std::filesystem::resize_file(dir / "box.ply", full - 50 * face_record_bytes - 5);
  expect_refusal([&] { read_mesh(dir / "box.ply"); },
                 "truncated PLY box.ply: " + vertices + " of " + vertices + " vertices, 141 of 192 faces");
  // Cut inside the vertices: 10 whole vertices (3 floats each) and a part of the eleventh.
  const auto body = full - 192 * face_record_bytes - box.V.rows() * 12;
  std::filesystem::resize_file(dir / "box.ply", body + 10 * 12 + 7);
  expect_refusal([&] { read_mesh(dir / "box.ply"); }, "truncated PLY box.ply: 10 of " + vertices + " vertices, 0 of 192 faces");
  std::filesystem::resize_file(dir / "box.ply", body);
  expect_refusal([&] { read_mesh(dir / "box.ply"); }, "truncated PLY box.ply: 0 of " + vertices + " vertices");
}

TEST(MeshBadInput, TruncatedAsciiPly) {
  test::TempDir dir("truncated-ascii-ply");
  const TriMesh box = small_box();
  test::write_ascii_ply_raw(dir / "box.ply", box);
  EXPECT_EQ(read_mesh(dir / "box.ply").mesh.triangle_count(), 192);  // the whole file is good
  const auto full = std::filesystem::file_size(dir / "box.ply");
  std::filesystem::resize_file(dir / "box.ply", full - 3);  // the last face loses its last index
  expect_refusal([&] { read_mesh(dir / "box.ply"); }, "191 of 192 faces");
  std::filesystem::resize_file(dir / "box.ply", full / 3);
  expect_refusal([&] { read_mesh(dir / "box.ply"); }, "truncated PLY box.ply: ");
}

TEST(MeshBadInput, PlyHeaderWithUnknownTypeOrFormat) {
  test::TempDir dir("ply-header");
  test::write_text(dir / "type.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float128 x\n"
                                      "element face 1\nproperty list uchar int vertex_indices\nend_header\n");
  expect_refusal([&] { read_mesh(dir / "type.ply"); }, "unknown property type 'float128'");
  test::write_text(dir / "format.ply", "ply\nformat binary_middle_endian 1.0\nelement face 1\nend_header\n");
  expect_refusal([&] { read_mesh(dir / "format.ply"); }, "unknown format 'binary_middle_endian'");
}

// Found by tests/fuzz/obj_fuzz.cpp: OpenMesh's OBJ reader asserts (and aborts the daemon) on a
// face corner with a texture or normal number but no vertex number.
TEST(MeshBadInput, ObjFaceCornerWithoutVertexNumber) {
  test::TempDir dir("obj-corner");
  test::write_text(dir / "corner.obj", "v 0 0 0\nv 250 0 0\nv 0 90 0\nvt 0 0\nvn 0 0 1\n  f /1 2/1 3/1\n");
  expect_refusal([&] { read_mesh(dir / "corner.obj"); }, "a face on line 6 of OBJ corner.obj has a corner without a vertex number");
  test::write_text(dir / "normal.obj", "v 0 0 0\nv 250 0 0\nv 0 90 0\nvn 0 0 1\nf 1//1 2//1 //1\n");
  expect_refusal([&] { read_mesh(dir / "normal.obj"); }, "line 5 of OBJ normal.obj");
}

// Found by tests/fuzz/ply_fuzz.cpp: OpenMesh's PLY header reader loops for ever when a version or
// count is not a number it can read or a line lacks its last word, so the header check refuses them.
TEST(MeshBadInput, PlyHeadersThatWouldHangOpenMesh) {
  test::TempDir dir("ply-hang");
  const std::string body = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  test::write_text(dir / "version.ply", "ply\nformat ascii form\n" + body);
  expect_refusal([&] { read_mesh(dir / "version.ply"); }, "the format line has no version number");
  test::write_text(dir / "first.ply", "ply\ncomment scanner\nformat ascii 1.0\n" + body);
  expect_refusal([&] { read_mesh(dir / "first.ply"); }, "the line after 'ply' must be the format line");
  test::write_text(dir / "count.ply", "ply\nformat ascii 1.0\nelement vertex 5000000000\nproperty float x\nend_header\n");
  expect_refusal([&] { read_mesh(dir / "count.ply"); }, "element count 5000000000 is too large");
  test::write_text(dir / "name.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float\nend_header\n0\n");
  expect_refusal([&] { read_mesh(dir / "name.ply"); }, "a property line without a name");
  test::write_text(dir / "unknown.ply", "ply\nformat ascii 1.0\npristoperty list uchar int vertex_indices\n" + body);
  expect_refusal([&] { read_mesh(dir / "unknown.ply"); }, "unknown header line 'pristoperty'");
  test::write_text(dir / "extra.ply", "ply\nformat ascii 1.0\nelement vertex 3 element\n" + body);
  expect_refusal([&] { read_mesh(dir / "extra.ply"); }, "'element' too many on a element line");
  test::write_text(dir / "value.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                       "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                       "end_header\n0 0 0\n1 0 0-4\n0 1 0\n3 0 1 2\n");
  expect_refusal([&] { read_mesh(dir / "value.ply"); }, "a value that is not a number: '0-4'");
}

// Found by tests/fuzz/off_fuzz.cpp: OpenMesh reads the counts after the header line as unsigned
// ints, so "-3" made it reserve room for 4294967293 vertices (out of memory).
TEST(MeshBadInput, OffCountsThatAreNoCounts) {
  test::TempDir dir("off-counts");
  test::write_text(dir / "negative.off", "OFF\n-3 1 0\n0 0 0\n");
  expect_refusal([&] { read_mesh(dir / "negative.off"); }, "'-3' is not a count");
  test::write_text(dir / "header.off", "OFF 3 1 0\n-3 1 0\n0 0 0\n");
  expect_refusal([&] { read_mesh(dir / "header.off"); }, "'-3' is not a count");
  test::write_text(dir / "binary.off", "OFF BINARY\n");
  expect_refusal([&] { read_mesh(dir / "binary.off"); }, "binary OFF is not read");
  // A value OpenMesh would read in part ("7-4") shifts the stream: "-4" became a face of 4 billion corners.
  const std::string vertices = "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  test::write_text(dir / "shifted.off", vertices + "3 0 1 2\n3 0 1 3-4 0 1 2\n");
  expect_refusal([&] { read_mesh(dir / "shifted.off"); }, "face 2 has '3-4' for a vertex number");
  test::write_text(dir / "value.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1-2 0\n0 0 1\n3 0 1 2\n");
  expect_refusal([&] { read_mesh(dir / "value.off"); }, "vertex value '1-2' is not a number");
  test::write_text(dir / "huge.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1e40 0\n0 0 1\n3 0 1 2\n");
  expect_refusal([&] { read_mesh(dir / "huge.off"); }, "vertex value '1e40' is out of range");
  test::write_text(dir / "colour.off", vertices + "3 0 1 2 255 0 0\n3 0 1 3\n");
  expect_refusal([&] { read_mesh(dir / "colour.off"); }, "face 1 has more values than its corners");
  // OpenMesh drops what follows x y z on a vertex line; counting it as a face shifted the faces.
  test::write_text(dir / "rest.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1 3\n3 0 1 2\n5000000000 0 1 3\n");
  expect_refusal([&] { read_mesh(dir / "rest.off"); }, "face 2 has '5000000000' for its number of corners");
  test::write_text(dir / "corners.off", vertices + "5000000000 0 1 2\n3 0 1 3\n");
  expect_refusal([&] { read_mesh(dir / "corners.off"); }, "face 1 has '5000000000' for its number of corners");
  // A header that claims far more vertices than the file holds: refused as truncated, without first
  // reserving room for 2 billion vertices (48 GB; the fuzzer found 10 GB with "OFF 444444202 7 2").
  test::write_text(dir / "claims.off", "OFF\n2147483647 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  expect_refusal([&] { read_mesh(dir / "claims.off"); }, "truncated OFF claims.off: 4 of 2147483647 vertices");
}

TEST(MeshBadInput, NonManifoldMessIsRefused) {
  // Triangles fanned around shared edges: every edge carries three or more faces.
  test::TempDir dir("mess");
  std::string obj;
  for (int k = 0; k < 40; ++k) obj += "v " + std::to_string(100.0 * std::cos(k)) + " " + std::to_string(100.0 * std::sin(k)) + " " + std::to_string(3.0 * k) + "\n";
  for (int k = 2; k < 40; ++k) obj += "f 1 2 " + std::to_string(k + 1) + "\n";
  test::write_text(dir / "mess.obj", obj);
  expect_refusal([&] { read_mesh(dir / "mess.obj"); }, "non-manifold");
}

TEST(MeshBadInput, SeveralDisconnectedPieces) {
  test::TempDir dir("pieces");
  const TriMesh a = test::box_mesh({0, 0, 0}, {250, 90, 120}, 4);
  const TriMesh b = test::box_mesh({400, 0, 0}, {600, 90, 100}, 4);
  TriMesh both;
  both.V.resize(a.V.rows() + b.V.rows(), 3);
  both.V << a.V, b.V;
  both.F.resize(a.F.rows() + b.F.rows(), 3);
  both.F << a.F, (b.F.array() + static_cast<int>(a.V.rows())).matrix();
  test::write_obj_raw(dir / "two.obj", both.V, both.F);
  expect_refusal([&] { read_mesh(dir / "two.obj"); }, "several disconnected pieces (2 pieces, the second has");
}

TEST(MeshBadInput, AmbiguousUnitsAreRefusedUnlessGiven) {
  test::TempDir dir("units");
  TriMesh box = small_box();
  box.V /= 25.4;  // a last in inches: ~ 10 units long
  test::write_obj_raw(dir / "inches.obj", box.V, box.F);
  expect_refusal([&] { read_mesh(dir / "inches.obj"); }, "cannot tell the length unit");
  MeshReadOptions options;
  options.unit = LengthUnit::Inch;
  const MeshIntake intake = read_mesh(dir / "inches.obj", options);
  EXPECT_NEAR(bounding_box_size(intake.mesh).x(), 250.0, 1e-4);  // OpenMesh parses floats
}

TEST(CheckIsLast, FlatPlateTinyAndHugeAreNotLasts) {
  expect_refusal([] { check_is_last(test::box_mesh({0, 0, 0}, {260, 100, 3}, 6)); }, "not a shoe last: flat");
  expect_refusal([] { check_is_last(test::box_mesh({0, 0, 0}, {40, 20, 20}, 6)); }, "not a shoe last: ");
  expect_refusal([] { check_is_last(test::box_mesh({0, 0, 0}, {900, 300, 300}, 6)); }, "mm long (a last is 100..500 mm");
  expect_refusal([] { check_is_last(test::box_mesh({0, 0, 0}, {260, 100, 100}, 1)); }, "only 12 triangles");
  EXPECT_NO_THROW(check_is_last(test::box_mesh({0, 0, 0}, {260, 95, 120}, 6)));
}

}  // namespace
}  // namespace lastcut
