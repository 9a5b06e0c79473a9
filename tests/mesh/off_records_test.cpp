// The ASCII OFF records lastcut reads in its checking pass are the mesh OpenMesh's own OFF reader
// gives for the same file (the oracle): the same points to the bit, the same triangles, polygons
// fanned and bad faces counted alike - on a generated last and on a file with the forms a
// hand-written OFF carries (colours after x y z, signs, exponents, tabs, CRLF, quads).
#include <gtest/gtest.h>

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>

#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/mesh_file_checks.hpp"
#include "engine/mesh/soup_importer.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "test_meshes.hpp"

namespace lastcut {
namespace {

SoupImporter read_with_openmesh(const std::filesystem::path& path) {
  SoupImporter soup;
  OpenMesh::IO::Options options;
  EXPECT_TRUE(OpenMesh::IO::IOManager().read(path.string(), soup, options)) << path;
  return soup;
}

SoupImporter read_in_check(const std::filesystem::path& path) {
  SoupImporter soup;
  const MeshFileFacts facts = inspect_mesh_file(path, 1'000'000, &soup);
  EXPECT_TRUE(facts.records_read);
  return soup;
}

void expect_same_soup(const SoupImporter& ours, const SoupImporter& openmesh) {
  EXPECT_EQ(ours.points, openmesh.points);  // bit for bit: both round each value to float
  EXPECT_EQ(ours.triangles, openmesh.triangles);
  EXPECT_EQ(ours.polygons_fanned, openmesh.polygons_fanned);
  EXPECT_EQ(ours.faces_with_bad_indices, openmesh.faces_with_bad_indices);
  EXPECT_EQ(ours.face_records, openmesh.face_records);
}

TEST(OffRecords, AGeneratedLastReadsAsOpenMeshReadsIt) {
  test::TempDir dir("off-records-last");
  LastParams params;
  params.target_triangles = 3000;
  write_mesh(dir / "last.off", generate_last(params).mesh);
  const SoupImporter ours = read_in_check(dir / "last.off");
  EXPECT_EQ(ours.triangles.size(), 3000u);
  expect_same_soup(ours, read_with_openmesh(dir / "last.off"));
}

TEST(OffRecords, HandWrittenFormsReadAsOpenMeshReadsThem) {
  test::TempDir dir("off-records-forms");
  test::write_text(dir / "forms.off",
                   "OFF\r\n"
                   "6 4 0\n"
                   "0.1 +2.5 -3e-2\r\n"
                   "1.0000001 0 0 255 0 0\n"        // a colour after x y z: skipped
                   "\t0\t1E2\t0.33333333333\n"
                   "1e-7 -0 4.\n"
                   "7 8 9\n"
                   ".5 -.5 123456789.123\n"
                   "3 0 1 2\n"
                   "4 0 2 3 4\n"                    // a quad, fanned
                   "3 1 2 9\n"                      // a corner past the last vertex: skipped, counted
                   "3 3 4 5\r\n");
  const SoupImporter ours = read_in_check(dir / "forms.off");
  EXPECT_EQ(ours.points.size(), 6u);
  EXPECT_EQ(ours.triangles.size(), 4u);
  EXPECT_EQ(ours.polygons_fanned, 1);
  EXPECT_EQ(ours.faces_with_bad_indices, 1);
  EXPECT_EQ(ours.points[0][1], 2.5);
  EXPECT_EQ(ours.points[0][0], static_cast<double>(0.1f));
  expect_same_soup(ours, read_with_openmesh(dir / "forms.off"));
}

// OpenMesh's reader gives nothing for an OFF with '#' comments (it refused such files before); the
// checking pass skips them, as the OFF format allows.
TEST(OffRecords, CommentsAreSkipped) {
  test::TempDir dir("off-records-comments");
  test::write_text(dir / "comments.off",
                   "OFF # made by hand\n# 3 vertices, 1 face\n3 1 0\n0 0 0 # origin\n10 0 0\n0 10 0\n3 0 1 2 # one\n");
  const SoupImporter ours = read_in_check(dir / "comments.off");
  ASSERT_EQ(ours.points.size(), 3u);
  EXPECT_EQ(ours.points[1][0], 10.0);
  ASSERT_EQ(ours.triangles.size(), 1u);
  EXPECT_EQ(ours.triangles[0], (std::array<int, 3>{0, 1, 2}));
}

}  // namespace
}  // namespace lastcut
