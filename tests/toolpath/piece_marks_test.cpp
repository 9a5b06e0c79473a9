// Marks on a piece beyond its label (issue 35, labels and marks): lines drawn with the pen and
// never cut, turned with their piece; notches cut as the profile's [notch] says, a slit or a V,
// while the last's landmarks keep their slit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "engine/core/engine_error.hpp"
#include "engine/toolpath/layout_pieces.hpp"
#include "engine/toolpath/mark_stroke.hpp"
#include "engine/toolpath/plan_cut_program.hpp"
#include "test_layouts.hpp"

namespace lastcut::test {
namespace {

// A 100 x 60 mm piece at (100, 100) on the table, a notch on its bottom edge, two drawn lines.
PlacedPiece lined_piece() {
  PlacedPiece piece;
  piece.item_id = 7;
  piece.label = "vamp 42 L";
  piece.outline = Polygon2{{{100, 100}, {200, 100}, {200, 160}, {100, 160}}};
  piece.marks = {PlacedMark{"notch", {150, 100}, {150, 103}}};
  piece.drawn_lines_mm = {{{110, 110}, {190, 110}, {190, 150}}, {{120, 140}, {140, 150}}};
  return piece;
}

int strokes_of(const CutProgram& program, ToolRole role) {
  return static_cast<int>(std::count_if(program.tip_strokes.begin(), program.tip_strokes.end(),
                                        [role](const Stroke& stroke) { return stroke.tool == role; }));
}

// True when some stroke of `role` draws exactly `line`, in either direction.
bool drawn_as(const CutProgram& program, ToolRole role, const std::vector<Point2>& line) {
  std::vector<Point2> reversed(line.rbegin(), line.rend());
  for (const Stroke& stroke : program.tip_strokes)
    if (stroke.tool == role && (stroke.points_mm == line || stroke.points_mm == reversed)) return true;
  return false;
}

MachineProfile without_pen(MachineProfile profile) {
  profile.pen.reset();
  profile.label.enabled = false;
  return profile;
}

TEST(ToolpathDrawnLines, DrawnWithThePenBeforeTheContourNeverCut) {
  const MachineProfile profile = profile_named("hpgl-pen-plotter");
  PlacedPiece bare = lined_piece();
  bare.drawn_lines_mm.clear();
  const CutProgram labelled_only = plan_cut_program({bare}, profile);
  const CutProgram program = plan_cut_program({lined_piece()}, profile);
  EXPECT_EQ(strokes_of(program, ToolRole::Pen), strokes_of(labelled_only, ToolRole::Pen) + 2) << "the label and the two lines";
  EXPECT_EQ(strokes_of(program, ToolRole::Mark), 1);
  EXPECT_EQ(strokes_of(program, ToolRole::Cut), 1);
  for (const std::vector<Point2>& line : lined_piece().drawn_lines_mm) {
    EXPECT_TRUE(drawn_as(program, ToolRole::Pen, line));
    EXPECT_FALSE(drawn_as(program, ToolRole::Cut, line));
    EXPECT_FALSE(drawn_as(program, ToolRole::Mark, line));
  }
  EXPECT_TRUE(program.tip_strokes.back().closed_outline) << "lines first, the contour last";
}

TEST(ToolpathDrawnLines, LeftOutWithoutAPenEvenOutsideTheTable) {
  const MachineProfile profile = without_pen(profile_named("hpgl-pen-plotter"));
  PlacedPiece piece = lined_piece();
  piece.drawn_lines_mm.push_back({{150, 130}, {5000, 130}});  // beyond the table: not drawn, not refused
  const CutProgram program = plan_cut_program({piece}, profile);
  EXPECT_EQ(strokes_of(program, ToolRole::Pen), 0);
  EXPECT_EQ(strokes_of(program, ToolRole::Mark), 1);
  EXPECT_EQ(strokes_of(program, ToolRole::Cut), 1);
  for (const Stroke& stroke : program.tip_strokes)
    for (const std::vector<Point2>& line : piece.drawn_lines_mm)
      for (const Point2& point : line) EXPECT_GT(distance_to_polyline(point, stroke.points_mm), 1.0) << "nothing near a drawn line";
  // With a pen the same line is refused: it would be drawn off the table.
  try {
    plan_cut_program({piece}, profile_named("hpgl-pen-plotter"));
    ADD_FAILURE() << "a line off the table was accepted";
  } catch (const EngineError& error) {
    EXPECT_NE(std::string(error.what()).find("piece 1 (item 7 'vamp 42 L') reaches (5000, 130) mm"), std::string::npos)
        << error.what();
  }
}

TEST(ToolpathDrawnLines, TurnedAndMirroredWithTheirPiece) {
  NestInstance instance;
  instance.strip_height = 600;
  NestItem item;
  item.id = 5;
  item.shape = Polygon2{{{0, 0}, {100, 0}, {100, 60}, {0, 60}}};
  item.drawn_lines_mm = {{{10, 10}, {90, 10}, {90, 50}}};
  instance.items = {item};
  Layout layout;
  layout.placements = {Placement{5, -1, 0, 90, false, 300, 100}, Placement{5, -1, 0, 90, true, 500, 100}};
  const std::vector<PlacedPiece> pieces = placed_pieces(layout, instance, SheetRef{});
  ASSERT_EQ(pieces.size(), 2u);
  for (size_t p = 0; p < pieces.size(); ++p) {
    ASSERT_EQ(pieces[p].drawn_lines_mm.size(), 1u);
    std::vector<Point2> expected;
    for (const Point2& own : item.drawn_lines_mm[0]) expected.push_back(expected_point(own, layout.placements[p]));
    ASSERT_EQ(pieces[p].drawn_lines_mm[0].size(), expected.size());
    for (size_t k = 0; k < expected.size(); ++k) EXPECT_LT((pieces[p].drawn_lines_mm[0][k] - expected[k]).norm(), 1e-9) << p << " " << k;
  }
  // Turned by 90 deg: (10, 10) -> (-10, 10), moved to (290, 110).
  EXPECT_LT((pieces[0].drawn_lines_mm[0][0] - Point2(290, 110)).norm(), 1e-9);
  EXPECT_TRUE(drawn_as(plan_cut_program(pieces, profile_named("hpgl-pen-plotter")), ToolRole::Pen, pieces[1].drawn_lines_mm[0]));
}

MachineProfile v_notch_profile(const std::string& width_line) {
  std::string text = read_text(std::filesystem::path(LASTCUT_SOURCE_DIR) / "config/machines/hpgl-pen-plotter.toml");
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"shape = \"slit\"", "shape = \"v\"   "},
                                 std::pair<std::string, std::string>{"v_width_mm = 2.0", width_line}}) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  return parse_machine_profile(text, "v.toml");
}

std::vector<Stroke> mark_strokes(const CutProgram& program) {
  std::vector<Stroke> marks;
  std::copy_if(program.tip_strokes.begin(), program.tip_strokes.end(), std::back_inserter(marks),
               [](const Stroke& stroke) { return stroke.tool == ToolRole::Mark; });
  return marks;
}

TEST(ToolpathNotches, VNotchOpensAcrossTheMarkAndClosesAtItsInnerEnd) {
  const MachineProfile profile = v_notch_profile("v_width_mm = 2.0");
  ASSERT_EQ(profile.notch.shape, NotchShape::V);
  // A notch along a slant, so "across" is not an axis of the table.
  PlacedPiece piece = lined_piece();
  const Point2 from(150, 100), to = from + 3.0 * Point2(0.6, 0.8);
  piece.marks = {PlacedMark{"notch", from, to}};
  const std::vector<Stroke> marks = mark_strokes(plan_cut_program({piece}, profile));
  ASSERT_EQ(marks.size(), 1u);
  const std::vector<Point2>& v = marks[0].points_mm;
  ASSERT_EQ(v.size(), 3u) << "one stroke: in, to the inner end, out";
  EXPECT_NEAR((v[2] - v[0]).norm(), 2.0, 1e-9) << "the ends 2 mm apart";
  EXPECT_NEAR((v[2] - v[0]).dot(to - from), 0.0, 1e-9) << "measured across the mark";
  EXPECT_LT((0.5 * (v[0] + v[2]) - from).norm(), 1e-9) << "centred on the outline point";
  EXPECT_LT((v[1] - to).norm(), 1e-12) << "the middle at the inner end";
  // Another width, and a landmark keeps its slit on the same machine.
  const MachineProfile wide = v_notch_profile("v_width_mm = 4.5");
  piece.marks = {PlacedMark{"notch", from, to}, PlacedMark{"toe", {200, 130}, {198, 130}}};
  const std::vector<Stroke> both = mark_strokes(plan_cut_program({piece}, wide));
  ASSERT_EQ(both.size(), 2u);
  for (const Stroke& stroke : both) {
    if (stroke.points_mm.size() == 3) {
      EXPECT_NEAR((stroke.points_mm[2] - stroke.points_mm[0]).norm(), 4.5, 1e-9);
    } else {
      ASSERT_EQ(stroke.points_mm.size(), 2u);
      const bool slit = (stroke.points_mm[0] == Point2(200, 130) && stroke.points_mm[1] == Point2(198, 130)) ||
                        (stroke.points_mm[1] == Point2(200, 130) && stroke.points_mm[0] == Point2(198, 130));
      EXPECT_TRUE(slit) << "the toe landmark is the slit it was";
    }
  }
}

TEST(ToolpathNotches, SlitByDefaultAndTheLandmarkRule) {
  const MachineProfile profile = profile_named("hpgl-pen-plotter");
  EXPECT_EQ(profile.notch.shape, NotchShape::Slit);
  const std::vector<Stroke> marks = mark_strokes(plan_cut_program({lined_piece()}, profile));
  ASSERT_EQ(marks.size(), 1u);
  EXPECT_EQ(marks[0].points_mm.size(), 2u);
  for (const char* landmark : {"toe", "heel", "top_front", "top_back"}) EXPECT_TRUE(is_landmark_mark(landmark)) << landmark;
  for (const char* notch : {"notch", "balance_seam_front_2", "vamp 2", "vamp x front seam", "Toe", "toe "})
    EXPECT_FALSE(is_landmark_mark(notch)) << notch;
  const NotchOptions v{NotchShape::V, 2.0};
  EXPECT_TRUE(mark_stroke(PlacedMark{"notch", {1, 1}, {1, 1}}, v).empty()) << "a mark of no length cuts nothing";
  EXPECT_EQ(mark_stroke(PlacedMark{"heel", {0, 0}, {0, 2}}, v).size(), 2u);
}

TEST(ToolpathNotches, AVNotchBesideTheTableEdgeIsRefused) {
  // The outline point on the table's edge x = 0 is fine for a slit; a V's arm reaches past it.
  PlacedPiece piece;
  piece.item_id = 2;
  piece.outline = Polygon2{{{0, 50}, {80, 50}, {80, 100}, {0, 100}}};
  piece.marks = {PlacedMark{"notch", {0.5, 50}, {0.5, 53}}};
  EXPECT_NO_THROW(plan_cut_program({piece}, without_pen(profile_named("hpgl-pen-plotter"))));
  MachineProfile v = without_pen(profile_named("hpgl-pen-plotter"));
  v.notch = NotchOptions{NotchShape::V, 2.0};
  try {
    plan_cut_program({piece}, v);
    ADD_FAILURE() << "a V off the table was accepted";
  } catch (const EngineError& error) {
    EXPECT_NE(std::string(error.what()).find("piece 1 (item 2) reaches (-0.5, 50) mm"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace lastcut::test
