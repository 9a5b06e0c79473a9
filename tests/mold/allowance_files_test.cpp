// A mold with per-edge allowances and balance notches in its files: the DXF keeps the cut outline,
// the notches and the net line (on its own layer NET), the SVG draws the net line, and the cut
// file made from the mold cuts only the outline and the notches, never the net line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/mold/mold.hpp"
#include "engine/mold/mold_dxf.hpp"
#include "engine/mold/mold_svg.hpp"
#include "engine/nest/mold_items.hpp"
#include "engine/toolpath/cut_file.hpp"
#include "engine/toolpath/layout_pieces.hpp"
#include "engine/toolpath/plan_cut_program.hpp"
#include "tests/mold/synthetic_patch.hpp"
#include "tests/toolpath/test_layouts.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

Mold allowance_mold() {
  const auto patch = test::mold_like_patch(720, 6);
  const std::map<std::string, int> landmarks = {{"top_front", test::mold_rim_vertex(patch, 50)},
                                                {"top_back", test::mold_rim_vertex(patch, 150)},
                                                {"heel", test::mold_rim_vertex(patch, 195)},
                                                {"toe", test::mold_rim_vertex(patch, 345)}};
  MoldOptions options;
  options.edge_allowances = EdgeAllowances{15, 5, 0};
  options.balance_notches = BalanceNotches{25, 50};
  return make_mold("medial", patch.UV, patch.F, landmarks, options);
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(AllowanceFiles, DxfRoundTripKeepsOutlineMarksAndTheNetLineOnItsOwnLayer) {
  const fs::path dir = test::scratch_dir("mold-allowance-dxf");
  const Mold mold = allowance_mold();
  ASSERT_FALSE(mold.net.points.empty());
  ASSERT_GT(mold.marks.size(), 8u);
  write_mold_dxf(dir / "medial.dxf", mold);
  const std::string text = read_text(dir / "medial.dxf");
  EXPECT_NE(text.find("POLYLINE\n8\nNET\n"), std::string::npos);
  EXPECT_NE(text.find("POLYLINE\n8\nCUT\n"), std::string::npos);

  const Mold back = read_mold_dxf(dir / "medial.dxf");
  ASSERT_EQ(back.outline.points.size(), mold.outline.points.size());
  for (size_t i = 0; i < mold.outline.points.size(); ++i)
    ASSERT_LT((back.outline.points[i] - mold.outline.points[i]).norm(), 2e-6);
  ASSERT_EQ(back.net.points.size(), mold.net.points.size());
  for (size_t i = 0; i < mold.net.points.size(); ++i) ASSERT_LT((back.net.points[i] - mold.net.points[i]).norm(), 2e-6);
  ASSERT_EQ(back.marks.size(), mold.marks.size());
  for (size_t i = 0; i < mold.marks.size(); ++i) {
    EXPECT_EQ(back.marks[i].name, mold.marks[i].name);
    EXPECT_LT((back.marks[i].position_mm - mold.marks[i].position_mm).norm(), 2e-6);
  }

  // A mold without allowance has no NET layer entity: its outline is the net line.
  Mold plain = mold;
  plain.net = {};
  write_mold_dxf(dir / "plain.dxf", plain);
  EXPECT_EQ(read_text(dir / "plain.dxf").find("POLYLINE\n8\nNET\n"), std::string::npos);
  EXPECT_TRUE(read_mold_dxf(dir / "plain.dxf").net.points.empty());
  fs::remove_all(dir);
}

TEST(AllowanceFiles, SvgDrawsTheNetLineDashed) {
  const fs::path dir = test::scratch_dir("mold-allowance-svg");
  const auto patch = test::mold_like_patch(720, 6);
  const Mold mold = allowance_mold();
  write_mold_svg(dir / "medial.svg", mold, patch.UV, patch.F, Eigen::VectorXd::Ones(patch.F.rows()));
  const std::string text = read_text(dir / "medial.svg");
  const auto net = text.find("<polygon id=\"net\"");
  ASSERT_NE(net, std::string::npos);
  EXPECT_NE(text.find("stroke-dasharray", net), std::string::npos);
  // One "x,y" pair per net point.
  const auto points = text.find("points=\"", net) + 8;
  const std::string list = text.substr(points, text.find('"', points) - points);
  EXPECT_EQ(static_cast<size_t>(std::count(list.begin(), list.end(), ',')), mold.net.points.size());
  EXPECT_NE(text.find("balance_feather_1"), std::string::npos);
  fs::remove_all(dir);
}

TEST(AllowanceFiles, TheCutFileCutsTheOutlineAndNotchesButNotTheNetLine) {
  const Mold mold = allowance_mold();
  NestInstance instance;
  instance.name = "allowance";
  instance.strip_height = 1000;
  instance.items = items_from_molds({mold}, MoldNestSpec{});
  Layout layout;
  layout.instance = instance.name;
  const Point2 shift(300.0, 200.0);
  layout.placements.push_back(Placement{0, -1, 0, 0.0, false, shift.x(), shift.y()});
  const MachineProfile profile = test::profile_named("grbl-drag-knife");
  const CutProgram program = plan_cut_program(placed_pieces(layout, instance, SheetRef{}), profile);

  Polygon2 cut_outline = mold.outline, net = mold.net;
  for (auto& p : cut_outline.points) p += shift;
  for (auto& p : net.points) p += shift;
  int cut_strokes = 0, mark_strokes = 0;
  for (const Stroke& stroke : program.tip_strokes) {
    if (stroke.tool == ToolRole::Cut) {
      ++cut_strokes;
      EXPECT_TRUE(test::traces_outline(stroke.points_mm, cut_outline, 0.01));
    }
    if (stroke.tool == ToolRole::Mark) {
      ++mark_strokes;
      // A notch has one end on the cut outline and is kNotchLength_mm long (the planner may cut
      // it from either end).
      EXPECT_LT(std::min(test::distance_to_outline(stroke.points_mm.front(), cut_outline),
                         test::distance_to_outline(stroke.points_mm.back(), cut_outline)),
                1e-6);
      EXPECT_NEAR(polyline_length(stroke.points_mm), kNotchLength_mm, 1e-6);
    }
  }
  EXPECT_EQ(cut_strokes, 1);
  EXPECT_EQ(mark_strokes, static_cast<int>(mold.marks.size()));
  // The feather net line lies 15 mm inside the outline: no stroke of the knife comes near it.
  int far_net_points = 0;
  for (const Point2& p : net.points) {
    if (test::distance_to_outline(p, cut_outline) < 14.9) continue;
    ++far_net_points;
    for (const Stroke& stroke : program.tip_strokes)
      if (stroke.tool == ToolRole::Cut) {
        ASSERT_GT(test::distance_to_polyline(p, stroke.points_mm), 14.9);
      }
  }
  EXPECT_GT(far_net_points, 20);
}

}  // namespace
}  // namespace lastcut
