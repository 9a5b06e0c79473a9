// Repairs are made and counted exactly on meshes with planted defects: duplicate vertices,
// flipped faces, duplicate and degenerate faces, a non-manifold fin, scanner debris, and a
// whole scan saved inside out.
#include <gtest/gtest.h>

#include "engine/core/engine_error.hpp"
#include "engine/mesh/read_mesh.hpp"
#include "test_meshes.hpp"
#include "tests/lastgen/mesh_checks.hpp"

namespace lastcut {
namespace {

TriMesh clean_box() { return test::box_mesh({0, 0, 0}, {250, 90, 120}, 4); }  // 192 faces

TEST(MeshRepair, CleanBoxNeedsNoRepair) {
  test::TempDir dir("clean");
  const TriMesh box = clean_box();
  test::write_obj_raw(dir / "box.obj", box.V, box.F);
  const MeshIntake intake = read_mesh(dir / "box.obj");
  const IntakeReport& r = intake.report;
  EXPECT_EQ(r.format, "OBJ");
  EXPECT_EQ(r.triangles_read, 192);
  EXPECT_EQ(r.duplicate_vertices_merged + r.degenerate_faces_removed + r.duplicate_faces_removed + r.faces_flipped +
                r.non_manifold_faces_removed + r.loose_components_removed + r.boundary_loops,
            0);
  EXPECT_EQ(intake.mesh.triangle_count(), 192);
  EXPECT_NEAR(test::signed_volume_mm3(intake.mesh), 250.0 * 90.0 * 120.0, 1e-6);
  EXPECT_NE(r.unit_note.find("millimetres"), std::string::npos) << r.unit_note;
}

TEST(MeshRepair, PlantedDefectsAreRepairedAndCounted) {
  TriMesh box = clean_box();
  const int original_vertices = static_cast<int>(box.V.rows());
  // 1. Faces 0..9 get their own exact copies of their corner vertices: 30 duplicates.
  Eigen::MatrixXd V(original_vertices + 30 + 4, 3);
  V.topRows(original_vertices) = box.V;
  int next = original_vertices;
  for (int f = 0; f < 10; ++f)
    for (int c = 0; c < 3; ++c) {
      V.row(next) = box.V.row(box.F(f, c));
      box.F(f, c) = next++;
    }
  // 2. Seven faces flipped.
  for (int f = 50; f < 57; ++f) box.F.row(f) = Eigen::RowVector3i(box.F(f, 0), box.F(f, 2), box.F(f, 1));
  // 3. A speck of debris far away (one triangle) and a collinear vertex on an existing edge.
  V.row(next++) = Eigen::RowVector3d(1000, 1000, 1000);
  V.row(next++) = Eigen::RowVector3d(1001, 1000, 1000);
  V.row(next++) = Eigen::RowVector3d(1000, 1001, 1000);
  const int a = box.F(100, 0), b = box.F(100, 1);
  V.row(next++) = 0.5 * (V.row(a) + V.row(b));
  std::vector<Eigen::RowVector3i> extra{
      {next - 4, next - 3, next - 2},                                    // debris
      box.F.row(120), box.F.row(121), box.F.row(122),                   // 3 exact duplicate faces
      Eigen::RowVector3i(box.F(130, 0), box.F(130, 2), box.F(130, 1)),  // a reversed duplicate
      Eigen::RowVector3i(box.F(140, 0), box.F(140, 0), box.F(140, 1)),  // repeated corner
      Eigen::RowVector3i(box.F(141, 2), box.F(141, 1), box.F(141, 1)),  // repeated corner
      Eigen::RowVector3i(a, next - 1, b),                               // zero area
  };
  Eigen::MatrixXi F(box.F.rows() + static_cast<Eigen::Index>(extra.size()), 3);
  F.topRows(box.F.rows()) = box.F;
  for (size_t k = 0; k < extra.size(); ++k) F.row(box.F.rows() + static_cast<Eigen::Index>(k)) = extra[k];

  test::TempDir dir("planted");
  test::write_obj_raw(dir / "planted.obj", V, F);
  const MeshIntake intake = read_mesh(dir / "planted.obj");
  const IntakeReport& r = intake.report;
  EXPECT_EQ(r.triangles_read, 192 + 8);
  EXPECT_EQ(r.duplicate_vertices_merged, 30);
  EXPECT_EQ(r.degenerate_faces_removed, 3);
  EXPECT_EQ(r.duplicate_faces_removed, 4);
  EXPECT_EQ(r.faces_flipped, 7);
  EXPECT_EQ(r.non_manifold_faces_removed, 0);
  EXPECT_EQ(r.loose_components_removed, 1);
  EXPECT_EQ(r.boundary_loops, 0);
  EXPECT_EQ(intake.mesh.triangle_count(), 192);
  EXPECT_EQ(intake.mesh.vertex_count(), original_vertices);
  EXPECT_NEAR(test::signed_volume_mm3(intake.mesh), 250.0 * 90.0 * 120.0, 1e-6);
}

TEST(MeshRepair, InsideOutScanIsTurnedOutward) {
  TriMesh box = clean_box();
  box.F.col(1).swap(box.F.col(2));
  test::TempDir dir("inside-out");
  test::write_obj_raw(dir / "inside_out.obj", box.V, box.F);
  const MeshIntake intake = read_mesh(dir / "inside_out.obj");
  EXPECT_EQ(intake.report.faces_flipped, 192);
  EXPECT_NEAR(test::signed_volume_mm3(intake.mesh), 250.0 * 90.0 * 120.0, 1e-6);
}

TEST(MeshRepair, FinOnAnEdgeAndBowTieAreCutAway) {
  TriMesh box = clean_box();
  Eigen::MatrixXd V(box.V.rows() + 3, 3);
  V.topRows(box.V.rows()) = box.V;
  const Eigen::Index n = box.V.rows();
  // A fin: a third face on the edge of face 0, and a bow tie: a triangle touching only vertex 0
  // of face 60 from outside.
  V.row(n) = Eigen::RowVector3d(125, -50, 60);
  const int p = box.F(60, 0);
  V.row(n + 1) = V.row(p) + Eigen::RowVector3d(-10, -10, 3);
  V.row(n + 2) = V.row(p) + Eigen::RowVector3d(-10, -3, 10);
  Eigen::MatrixXi F(box.F.rows() + 2, 3);
  F.topRows(box.F.rows()) = box.F;
  F.row(box.F.rows()) << box.F(0, 0), box.F(0, 1), static_cast<int>(n);
  F.row(box.F.rows() + 1) << p, static_cast<int>(n + 1), static_cast<int>(n + 2);
  test::TempDir dir("fin");
  test::write_obj_raw(dir / "fin.obj", V, F);
  const MeshIntake intake = read_mesh(dir / "fin.obj");
  // The three faces on the crowded edge go (leaving one hole); the bow tie's small fan goes.
  EXPECT_EQ(intake.report.non_manifold_faces_removed, 4);
  EXPECT_EQ(intake.report.boundary_loops, 1);
  EXPECT_EQ(intake.mesh.triangle_count(), 192 - 2);
  EXPECT_GT(test::signed_volume_mm3(intake.mesh), 0.0);
}

}  // namespace
}  // namespace lastcut
