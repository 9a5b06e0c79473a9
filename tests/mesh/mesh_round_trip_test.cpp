// A generated last survives write + read in all four formats unchanged (up to float precision),
// units are found (metres, centimetres) or taken as given, and the reference foot scan from
// /work/shared/data (metres) loads as a ~270 mm foot.
#include <gtest/gtest.h>

#include "engine/core/engine_error.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/read_mesh.hpp"
#include "test_meshes.hpp"
#include "tests/lastgen/mesh_checks.hpp"

namespace lastcut {
namespace {

const TriMesh& sample_last() {
  static const TriMesh mesh = [] {
    LastParams params;
    params.target_triangles = 3000;
    params.side = FootSide::Right;
    return generate_last(params).mesh;
  }();
  return mesh;
}

class RoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(RoundTrip, GeneratedLastComesBackUnchanged) {
  test::TempDir dir("round-trip");
  const std::filesystem::path path = dir / ("last" + GetParam());
  write_mesh(path, sample_last());
  const MeshIntake intake = read_mesh(path);
  const IntakeReport& r = intake.report;
  EXPECT_EQ(r.triangles_read, 3000);
  EXPECT_EQ(intake.mesh.triangle_count(), 3000);
  EXPECT_EQ(intake.mesh.vertex_count(), sample_last().vertex_count());
  EXPECT_EQ(r.duplicate_vertices_merged, 0);
  EXPECT_EQ(r.degenerate_faces_removed + r.duplicate_faces_removed + r.faces_flipped + r.non_manifold_faces_removed, 0);
  EXPECT_EQ(r.boundary_loops, 0);
  EXPECT_TRUE(bounding_box_size(intake.mesh).isApprox(bounding_box_size(sample_last()), 1e-5));
  EXPECT_NEAR(test::signed_volume_mm3(intake.mesh) / test::signed_volume_mm3(sample_last()), 1.0, 1e-5);
  EXPECT_NO_THROW(check_is_last(intake.mesh));
}

INSTANTIATE_TEST_SUITE_P(AllFormats, RoundTrip, ::testing::Values(".stl", ".obj", ".ply", ".off", ".STL"),
                         [](const auto& test_info) { return test_info.index == 4 ? std::string("upper_stl") : test_info.param.substr(1); });

TEST(MeshUnits, MetresAndCentimetresAreScaledToMillimetres) {
  test::TempDir dir("units");
  TriMesh metres = sample_last();
  metres.V /= 1000.0;
  write_mesh(dir / "metres.obj", metres);
  const MeshIntake m = read_mesh(dir / "metres.obj");
  EXPECT_NE(m.report.unit_note.find("metres"), std::string::npos) << m.report.unit_note;
  EXPECT_NEAR(bounding_box_size(m.mesh).x(), bounding_box_size(sample_last()).x(), 1e-3);

  TriMesh centimetres = sample_last();
  centimetres.V /= 10.0;
  write_mesh(dir / "cm.ply", centimetres);
  const MeshIntake c = read_mesh(dir / "cm.ply");
  EXPECT_NE(c.report.unit_note.find("centimetres"), std::string::npos) << c.report.unit_note;
  EXPECT_NEAR(bounding_box_size(c.mesh).x(), bounding_box_size(sample_last()).x(), 1e-3);

  MeshReadOptions forced;
  forced.unit = LengthUnit::Millimetre;
  const MeshIntake f = read_mesh(dir / "metres.obj", forced);
  EXPECT_LT(bounding_box_size(f.mesh).maxCoeff(), 1.0);
  EXPECT_THROW(check_is_last(f.mesh), EngineError);
}

TEST(MeshUnits, AsciiStlReadsLikeBinary) {
  test::TempDir dir("ascii");
  test::write_ascii_stl_raw(dir / "ascii.stl", sample_last());
  const MeshIntake intake = read_mesh(dir / "ascii.stl");
  EXPECT_EQ(intake.report.format, "ASCII STL");
  EXPECT_EQ(intake.mesh.triangle_count(), 3000);
  EXPECT_EQ(intake.report.boundary_loops, 0);
}

TEST(ReferenceData, FindFootTemplateInMetresLoadsAsA270MillimetreFoot) {
  const std::filesystem::path path = std::filesystem::path(LASTCUT_SHARED_DATA_DIR) / "meshes" / "find-template-foot.obj";
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const MeshIntake intake = read_mesh(path);
  EXPECT_NE(intake.report.unit_note.find("metres"), std::string::npos) << intake.report.unit_note;
  EXPECT_EQ(intake.report.triangles_read, 1750);
  const Eigen::Vector3d size = bounding_box_size(intake.mesh);
  EXPECT_NEAR(size.maxCoeff(), 270.0, 15.0);
  EXPECT_GT(test::signed_volume_mm3(intake.mesh), 0.0);
  EXPECT_NO_THROW(check_is_last(intake.mesh));  // a foot passes the coarse plausibility test
}

TEST(ReferenceData, HalfFootIsOneOpenDisk) {
  const std::filesystem::path path = std::filesystem::path(LASTCUT_SHARED_DATA_DIR) / "meshes" / "find-template-half-52k.off";
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const MeshIntake intake = read_mesh(path);
  EXPECT_EQ(intake.report.triangles_read, 52800);
  EXPECT_EQ(intake.report.boundary_loops, 1);
  EXPECT_EQ(intake.mesh.triangle_count(), 52800);
}

}  // namespace
}  // namespace lastcut

namespace lastcut {
namespace {

TEST(ShippedSamples, SampleLastsAreCleanClosedLasts) {
  for (const char* name : {"sample-last-eu42-left.stl", "sample-last-eu38-right.stl"}) {
    const std::filesystem::path path = std::filesystem::path(LASTCUT_SOURCE_DIR) / "config" / "samples" / name;
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    EXPECT_LT(std::filesystem::file_size(path), 3u * 1024 * 1024);
    const MeshIntake intake = read_mesh(path);
    EXPECT_EQ(intake.report.format, "binary STL");
    EXPECT_EQ(intake.mesh.triangle_count(), 50000) << name;
    EXPECT_EQ(intake.report.boundary_loops, 0) << name;
    EXPECT_EQ(intake.report.faces_flipped + intake.report.non_manifold_faces_removed, 0) << name;
    EXPECT_NO_THROW(check_is_last(intake.mesh)) << name;
  }
}

}  // namespace
}  // namespace lastcut
