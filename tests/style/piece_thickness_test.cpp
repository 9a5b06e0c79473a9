// A piece's surface moved off the last by its material's thickness (engine/style/piece_thickness.hpp),
// checked against geometry rather than against itself: a sphere's and a cylinder's patches moved d along
// their normals must grow in area as the parallel surfaces of radius R + d do, (1 + d/R)^2 and (1 + d/R),
// only the vertices may move, and a surface moved through its centre of curvature is refused. style.toml's
// thickness_mm is refused out of 0..10 mm in one exact line.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>

#include "daemon/config/style_folder.hpp"
#include "engine/style/piece_thickness.hpp"
#include "tests/flatten/flatten_fixtures.hpp"
#include "tests/support/engine_refusal.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

// Every vertex moved exactly offset_mm, and nothing but the vertices: the triangles are the same.
void expect_only_vertices_moved(const TriMesh& before, const TriMesh& after, double offset_mm) {
  ASSERT_EQ(after.V.rows(), before.V.rows());
  EXPECT_TRUE(after.F == before.F);
  EXPECT_NEAR((after.V - before.V).rowwise().norm().maxCoeff(), offset_mm, 1e-12);
  EXPECT_NEAR((after.V - before.V).rowwise().norm().minCoeff(), offset_mm, 1e-12);
}

// The area of the triangles with no corner on the outline (mm^2): away from the outline every vertex
// normal is the surface's, averaged over triangles all round it.
double inner_area_mm2(const TriMesh& mesh) {
  std::map<std::pair<int, int>, int> faces_on;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      ++faces_on[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<char> on_outline(static_cast<std::size_t>(mesh.V.rows()), 0);
  for (const auto& [edge, count] : faces_on)
    if (count == 1) on_outline[static_cast<std::size_t>(edge.first)] = on_outline[static_cast<std::size_t>(edge.second)] = 1;
  const Eigen::VectorXd areas = triangle_areas(mesh);
  double sum_mm2 = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    if (!on_outline[static_cast<std::size_t>(mesh.F(f, 0))] && !on_outline[static_cast<std::size_t>(mesh.F(f, 1))] &&
        !on_outline[static_cast<std::size_t>(mesh.F(f, 2))])
      sum_mm2 += areas(f);
  return sum_mm2;
}

// Away from the outline the parallel surface's growth holds to the mesh's faceting, within 1 % of the
// growth (measured 0.8 % on the cap, 0.6 % on the cylinder). On the outline the surface's normal, a mean
// over 2 mm, is one-sided and leans towards the patch: the outline moves a little inward and the whole
// patch grows less, measured 2.6 % of the growth on the cap and 3.4 % on the cylinder; 5 % is allowed.
constexpr double kInnerGrowthTolerance = 0.01;
constexpr double kWholeGrowthTolerance = 0.05;

// The patch moved d along its normals, against the parallel surface's growth `expected` (a function of d).
template <typename ExpectedGrowth>
void expect_growth(const char* what, const TriMesh& patch, ExpectedGrowth expected) {
  for (const double offset_mm : {0.6, 0.75, 2.0}) {
    const TriMesh moved = offset_along_normals(patch, offset_mm);
    expect_only_vertices_moved(patch, moved, offset_mm);
    const double inner = inner_area_mm2(moved) / inner_area_mm2(patch) - 1, whole = surface_area(moved) / surface_area(patch) - 1;
    std::printf("%s, d %.2f mm: inner area %+.4f %%, whole %+.4f %% (parallel surface: %+.4f %%)\n", what, offset_mm, 100 * inner,
                100 * whole, 100 * expected(offset_mm));
    EXPECT_NEAR(inner, expected(offset_mm), kInnerGrowthTolerance * expected(offset_mm)) << what << ", d " << offset_mm;
    EXPECT_NEAR(whole, expected(offset_mm), kWholeGrowthTolerance * expected(offset_mm)) << what << ", d " << offset_mm;
    EXPECT_LT(whole, expected(offset_mm)) << what << ", d " << offset_mm;
  }
}

TEST(PieceThickness, SphericalCapGrowsAsTheSphereOfRadiusRPlusD) {
  constexpr double kRadius_mm = 40;
  const TriMesh cap = testing::spherical_cap(kRadius_mm, 60, 30, 120);
  ASSERT_GT(vertex_normals(cap).row(0).z(), 0.99);  // outward: the leather lies on this side
  expect_growth("sphere R 40 mm", cap, [](double d) { return std::pow(1 + d / kRadius_mm, 2) - 1; });
}

TEST(PieceThickness, CylinderPatchGrowsAsTheCylinderOfRadiusRPlusD) {
  constexpr double kRadius_mm = 35;  // about a last's girth round the instep
  // Columns 2.5 degrees wide on average, unevenly: the area weights of a vertex's two sides differ.
  const TriMesh patch = testing::cylinder_patch(kRadius_mm, 120, 100, 48, 30).mesh;
  expect_growth("cylinder R 35 mm", patch, [](double d) { return d / kRadius_mm; });
}

TEST(PieceThickness, NothingMovesAtZeroAndAFlatPieceKeepsItsArea) {
  const TriMesh cap = testing::spherical_cap(40, 60, 10, 40);
  EXPECT_TRUE(offset_along_normals(cap, 0).V == cap.V);
  const TriMesh square = testing::square_10mm();
  EXPECT_NEAR(surface_area(offset_along_normals(square, 1.5)), 100, 1e-9);
}

TEST(PieceThickness, TheMidSurfaceIsHalfTheThicknessOut) {
  EXPECT_EQ(mid_surface_offset_mm(1.5), 0.75);
  EXPECT_EQ(mid_surface_offset_mm(0), 0);
}

TEST(PieceThickness, ASurfaceMovedThroughItsCentreOfCurvatureIsRefused) {
  // The inside of a 5 mm cylinder (its triangles turned round, so "outward" is towards the axis): moved
  // 6 mm it passes through the axis and its triangles turn over. How many depends on the faceting
  // (vertices whose normals lean sideways may turn twice): the line is checked round the count.
  TriMesh inside = testing::cylinder_patch(5, 120, 20, 24, 4).mesh;
  inside.F.col(1).swap(inside.F.col(2));
  const std::string refusal = test::engine_refusal([&] { offset_along_normals(inside, 6); });
  const std::string head = "moved 6 mm off the last the surface folds (", tail = " triangles turn over): the last curves inward tighter than that";
  ASSERT_GT(refusal.size(), head.size() + tail.size()) << refusal;
  EXPECT_EQ(refusal.substr(0, head.size()), head);
  EXPECT_EQ(refusal.substr(refusal.size() - tail.size()), tail);
  EXPECT_GT(std::stoi(refusal.substr(head.size())), inside.F.rows() / 2) << refusal;
  EXPECT_NO_THROW(offset_along_normals(inside, 2));  // well inside its centre of curvature it only shrinks
  EXPECT_EQ(test::engine_refusal([&] { offset_along_normals(inside, -1); }),
            "a surface can only be moved outward off the last, by a finite distance, not -1 mm");
  EXPECT_EQ(test::engine_refusal([&] { offset_along_normals(inside, NAN); }),
            "a surface can only be moved outward off the last, by a finite distance, not nan mm");
}

// A style.toml with one piece; its thickness lines as given.
std::string read_style_error(const test::TempDir& dir, const std::string& style_thickness, const std::string& piece_thickness) {
  std::ofstream(dir / "style.toml") << "name = \"thin\"\n"
                                       "lines = \"lines.obj\"\n"
                                    << style_thickness
                                    << "\n[reference]\n"
                                       "generated_eu_size = 42\n"
                                       "side = \"right\"\n"
                                       "[[piece]]\n"
                                       "name = \"vamp\"\n"
                                       "label = [0.0, 0.0, 0.0]\n"
                                    << piece_thickness << "\n";
  const Result<daemon::StyleFolder> folder = daemon::read_style_folder(dir.path());
  return folder ? "accepted" : folder.error();
}

TEST(PieceThickness, StyleTomlRefusesAThicknessOutsideZeroToTenMillimetres) {
  const test::TempDir dir("piece-thickness");
  const std::string file = (dir / "style.toml").string();
  EXPECT_EQ(read_style_error(dir, "", "thickness_mm = -0.5"), file + ": piece[1].thickness_mm (line 10): -0.5 is outside 0 .. 10");
  EXPECT_EQ(read_style_error(dir, "thickness_mm = 12.0", ""), file + ": thickness_mm (line 3): 12 is outside 0 .. 10");
  EXPECT_EQ(read_style_error(dir, "thickness_mm = \"1.2\"", ""), file + ": thickness_mm (line 3): must be a number");
  EXPECT_EQ(read_style_error(dir, "", "thickness_mm = nan"), file + ": piece[1].thickness_mm (line 10): nan is outside 0 .. 10");
}

TEST(PieceThickness, StyleTomlGivesEachPieceItsThicknessOrTheStyles) {
  const test::TempDir dir("piece-thickness-read");
  std::ofstream(dir / "lines.obj") << "o vamp\nv 0 0 0\nv 1 0 0\nl 1 2\n";
  EXPECT_EQ(read_style_error(dir, "thickness_mm = 1.2", "thickness_mm = 0.0"), "accepted");
  const Result<daemon::StyleFolder> folder = daemon::read_style_folder(dir.path());
  ASSERT_TRUE(folder) << folder.error();
  EXPECT_EQ(folder->style.thickness_mm, 1.2);
  ASSERT_EQ(folder->style.pieces.size(), 1u);
  EXPECT_EQ(folder->style.pieces[0].thickness_mm, 0.0);  // 0 given: off for this piece, not the style's
  EXPECT_EQ(read_style_error(dir, "", ""), "accepted");
  const Result<daemon::StyleFolder> plain = daemon::read_style_folder(dir.path());
  ASSERT_TRUE(plain) << plain.error();
  EXPECT_EQ(plain->style.thickness_mm, 0);  // default: off, the outputs of existing styles do not change
  EXPECT_FALSE(plain->style.pieces[0].thickness_mm);
}

}  // namespace
}  // namespace lastcut
