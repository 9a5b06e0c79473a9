// The planner's own rules: cutting order, start corners, overcut, marks and labels before the
// contour, label text and placement, knife adaptation, arc fitting, the stroke font.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>

#include "engine/toolpath/arc_fit.hpp"
#include "engine/toolpath/drag_knife.hpp"
#include "engine/toolpath/layout_pieces.hpp"
#include "engine/toolpath/piece_contour.hpp"
#include "engine/toolpath/piece_label.hpp"
#include "engine/toolpath/plan_cut_program.hpp"
#include "engine/toolpath/planar_geometry.hpp"
#include "engine/toolpath/stroke_font.hpp"
#include "engine/toolpath/tangential_knife.hpp"
#include "engine/toolpath/travel_order.hpp"
#include "test_layouts.hpp"

namespace lastcut::test {
namespace {

Polygon2 square(double x, double y, double side) { return Polygon2{{{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}}}; }

TEST(ToolpathTravelOrder, StopsOnALineAreVisitedInOrder) {
  std::vector<Point2> stops;
  for (int i : {7, 2, 9, 0, 5, 3, 8, 1, 6, 4}) stops.push_back(Point2(10.0 + 50.0 * i, 20.0));
  const std::vector<int> order = order_for_short_travel(stops, Point2::Zero());
  ASSERT_EQ(order.size(), stops.size());
  for (size_t k = 1; k < order.size(); ++k) EXPECT_LT(stops[order[k - 1]].x(), stops[order[k]].x());
}

TEST(ToolpathTravelOrder, ImprovesOnNearestNeighbourTrapAndOnTheGivenOrder) {
  // A grid of stops in a scrambled order (deterministic): the result is a permutation that beats
  // the given order by far and comes within 10 % of the boustrophedon path, which is optimal here.
  std::vector<Point2> stops;
  for (int k = 0; k < 64; ++k) {
    const int cell = (k * 37) % 64;
    stops.push_back(Point2(100.0 * (cell % 8), 100.0 * (cell / 8)));
  }
  std::vector<int> given(stops.size());
  std::iota(given.begin(), given.end(), 0);
  const std::vector<int> order = order_for_short_travel(stops, Point2::Zero());
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, given);
  const double ours_mm = open_path_length(stops, order, Point2::Zero());
  const double given_mm = open_path_length(stops, given, Point2::Zero());
  EXPECT_LT(ours_mm, 0.3 * given_mm);
  EXPECT_LE(ours_mm, open_path_length(stops, order_by_nearest_neighbour(stops, Point2::Zero()), Point2::Zero()) + 1e-9);
  EXPECT_LE(ours_mm, 1.1 * 63 * 100.0);
}

TEST(ToolpathPieceContour, StartsAtTheSharpestCornerAndOvercuts) {
  const NestInstance instance = shoe_instance();
  // Corners of the mold: toe end of the lasting edge (180, 0) turns ~92 deg, heel end (0, 0)
  // ~80 deg, heel point ~20 deg; the start is the toe end, wherever the tool is.
  const Polygon2& mold = instance.items[0].shape;
  const int start = contour_start_vertex(mold, Point2(-500, 500), 30.0);
  EXPECT_EQ(mold.points[start], Point2(180.0, 0.0));
  const std::vector<Point2> path = contour_cut_path(mold, start, 1.5);
  EXPECT_NEAR(polyline_length(path), perimeter(mold) + 1.5, 1e-9);
  EXPECT_EQ(path.front(), mold.points[start]);
  // A smooth outline (a circle) has no corner: the start is the vertex nearest the tool.
  Polygon2 circle;
  for (int i = 0; i < 72; ++i) circle.points.push_back(Point2(std::cos(i * std::numbers::pi / 36), std::sin(i * std::numbers::pi / 36)) * 50.0);
  EXPECT_FALSE(has_start_corner(circle, 30.0));
  EXPECT_EQ(contour_start_vertex(circle, Point2(0, -80), 30.0), 54);
}

TEST(ToolpathPlanCutProgram, MarksAndLabelBeforeEachContourAndShorterTravelThanLayoutOrder) {
  const NestInstance instance = shoe_instance();
  const Layout layout = shoe_layout();
  const auto pieces = placed_pieces(layout, instance, SheetRef{});
  const MachineProfile profile = profile_named("hpgl-pen-plotter");
  const CutProgram program = plan_cut_program(pieces, profile);
  ASSERT_EQ(program.pieces.size(), pieces.size());
  std::vector<int> contour_of_piece(pieces.size(), -1);
  for (size_t s = 0; s < program.strokes.size(); ++s) {
    const Stroke& stroke = program.strokes[s];
    ASSERT_GE(stroke.piece, 0);
    if (stroke.closed_outline) {
      EXPECT_EQ(contour_of_piece[stroke.piece], -1) << "one contour per piece";
      contour_of_piece[stroke.piece] = static_cast<int>(s);
    } else {
      EXPECT_EQ(contour_of_piece[stroke.piece], -1) << "mark or label after the contour of piece " << stroke.piece;
    }
    if (s > 0) {
      EXPECT_GE(stroke.piece, program.strokes[s - 1].piece) << "pieces are not interleaved";
    }
  }
  const CutStats ours = measure_program(program);
  const CutStats given = measure_program(plan_cut_program(pieces, profile, PieceOrder::AsGiven));
  EXPECT_LT(ours.travel_length_mm, given.travel_length_mm);
  EXPECT_NEAR(ours.cut_length_mm, given.cut_length_mm, 1e-6) << "the same cuts, in another order";
  EXPECT_EQ(ours.tool_lifts, static_cast<int>(program.strokes.size()));
}

TEST(ToolpathPieceLabel, TextFromTheItemLabelInsideThePiece) {
  EXPECT_EQ(piece_marking(3, "42 L medial"), "3 42 L");
  EXPECT_EQ(piece_marking(12, "strap EU41.5 right"), "12 41.5 R");
  EXPECT_EQ(piece_marking(1, ""), "1");
  // Labels made ready to draw (the daemon's) are written whole after the order number.
  EXPECT_EQ(piece_marking(4, "#4711 EU44 L med"), "4 #4711 EU44 L med");
  EXPECT_EQ(piece_marking(11, "#mueller-anna R lat"), "11 #mueller-anna R lat");
  const NestInstance instance = shoe_instance();
  const Layout layout = shoe_layout();
  const auto pieces = placed_pieces(layout, instance, SheetRef{});
  const CutProgram program = plan_cut_program(pieces, profile_named("hpgl-pen-plotter"));
  int labelled = 0;
  for (const Stroke& stroke : program.strokes) {
    if (stroke.tool != ToolRole::Pen) continue;
    for (const Point2& point : stroke.points_mm) {
      EXPECT_TRUE(point_in_ring(point, program.pieces[stroke.piece].outline_mm.points));
      EXPECT_GT(distance_to_boundary(point, program.pieces[stroke.piece].outline_mm), 0.5);
    }
  }
  for (const ProgramPiece& piece : program.pieces) labelled += !piece.marking.empty();
  EXPECT_EQ(labelled, static_cast<int>(pieces.size())) << "every test piece is big enough for a label";
  EXPECT_FALSE(place_text("1 42 L", square(0, 0, 5), 6.0, 2.5)) << "too small a piece gets no label";
}

TEST(ToolpathStrokeFont, EveryGlyphStaysInItsBoxAndUnknownCharactersAreDrawn) {
  const std::string all = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ-+./:()=_?#";
  for (char c : all) {
    const auto strokes = text_strokes(std::string(1, c), Point2(0, 0), 9.0);
    ASSERT_FALSE(strokes.empty()) << c;
    for (const auto& stroke : strokes) {
      EXPECT_GE(stroke.size(), 2u) << c;
      for (const Point2& p : stroke) {
        EXPECT_LE(std::abs(p.x()), 3.0 + 1e-9) << c;
        EXPECT_LE(std::abs(p.y()), 4.5 + 1e-9) << c;
      }
    }
  }
  EXPECT_EQ(text_strokes("a", Point2::Zero(), 9.0), text_strokes("A", Point2::Zero(), 9.0));
  EXPECT_EQ(text_strokes("~", Point2::Zero(), 9.0), text_strokes("?", Point2::Zero(), 9.0));
  EXPECT_NEAR(text_width_mm("12", 9.0), 14.0, 1e-12);
}

TEST(ToolpathDragKnife, SimulatedBladeTipCutsTheSquareCorners) {
  const Polygon2 outline = square(10, 10, 40);
  const std::vector<Point2> tip_path = contour_cut_path(outline, 0, 1.0);
  const DragKnifeOptions options{0.5, 10.0, 5.0};
  const std::vector<Point2> holder = compensate_drag_knife(tip_path, Point2(0, -1), options);
  const std::vector<Point2> tip = simulate_drag_knife_tip(holder, outline.points[0], 0.5, 0.005);
  EXPECT_TRUE(traces_outline(tip, outline, 0.01));
  for (const Point2& corner : outline.points) EXPECT_LT(distance_to_polyline(corner, tip), 0.01);
  // Without compensation the tip rounds the corners off by far more than the tolerance.
  const std::vector<Point2> naive = simulate_drag_knife_tip(tip_path, outline.points[0], 0.5, 0.005);
  EXPECT_GT(distance_to_polyline(outline.points[2], naive), 0.1);
}

TEST(ToolpathTangentialKnife, LiftsAtSharpCornersTurnsInPlaceAtMildOnesAngleStaysContinuous) {
  Stroke stroke;
  stroke.points_mm = {{0, 0}, {10, 0}, {20, 1}, {20, 11}, {10, 11}, {0, 0}};  // 5.7 deg, 84 deg, 90 deg, ...
  double angle_deg = 350.0;  // the axis is near 360: the first angle must be 360, not 0
  const std::vector<Stroke> parts = split_for_tangential_knife(stroke, 20.0, angle_deg);
  ASSERT_EQ(parts.size(), 4u);
  EXPECT_NEAR(parts[0].knife_angle_deg.front(), 360.0, 1e-9);
  double previous = parts[0].knife_angle_deg.front();
  for (const Stroke& part : parts) {
    ASSERT_EQ(part.points_mm.size(), part.knife_angle_deg.size());
    EXPECT_LE(std::abs(part.knife_angle_deg.front() - previous), 180.0);
    for (size_t k = 1; k < part.knife_angle_deg.size(); ++k) {
      EXPECT_LE(std::abs(part.knife_angle_deg[k] - part.knife_angle_deg[k - 1]), 20.0);
    }
    previous = part.knife_angle_deg.back();
  }
  EXPECT_EQ(parts[0].points_mm.size(), 4u) << "0,0 -> 10,0, turn in place, -> 20,1";
  EXPECT_EQ(angle_deg, previous);
}

TEST(ToolpathArcFit, CircleSamplesBecomeFewArcsWithinTolerance) {
  std::vector<Point2> points;
  for (int i = 0; i <= 170; ++i) points.push_back(Point2(100, 50) + 40.0 * Point2(std::cos(i * 0.02), std::sin(i * 0.02)));
  points.push_back(points.back() + Point2(10, 0));  // a straight tail stays a line
  const auto segments = fit_arcs(points, ArcFitOptions{0.01});
  EXPECT_LE(segments.size(), 4u);
  EXPECT_TRUE(segments.front().is_arc && segments.front().counter_clockwise);
  EXPECT_NEAR((segments.front().center_mm - Point2(100, 50)).norm(), 0.0, 0.01);
  EXPECT_FALSE(segments.back().is_arc);
  EXPECT_EQ(segments.back().end_mm, points.back());
  // A zig-zag is no arc.
  const auto zigzag = fit_arcs({{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}}, ArcFitOptions{0.01});
  for (const auto& segment : zigzag) EXPECT_FALSE(segment.is_arc);
}

}  // namespace
}  // namespace lastcut::test
