// Outward allowances (engine/mold/outward_allowance.hpp), measured on the result: an edge with no
// allowance stays exactly where it is even where the piece is narrower than its neighbour's allowance,
// and an edge with one lies that far inside the cut line; a change of allowance is a chamfer.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/engine_error.hpp"
#include "engine/mold/outline_geometry.hpp"
#include "engine/mold/outward_allowance.hpp"
#include "tests/support/outline_ray.hpp"

namespace lastcut {
namespace {

using test::ray_to_outline;

TEST(OutwardAllowance, RectangleWithALastingEdge) {
  Polygon2 net;
  net.points = {{0, 0}, {100, 0}, {100, 40}, {0, 40}};
  const std::vector<AllowanceEdge> edges = {{{{0, 0}, {100, 0}}, 18}, {{{100, 0}, {100, 40}}, 0},
                                            {{{100, 40}, {0, 40}}, 0}, {{{0, 40}, {0, 0}}, 0}};
  const Polygon2 cut = grow_outward_by_allowances(net, edges, 0.02);
  EXPECT_GT(signed_area(cut), 0);
  for (const double x : {10.0, 50.0, 90.0}) {
    EXPECT_NEAR(ray_to_outline(cut, {x, 0}, {0, -1}), 18, 1e-4) << x;
    EXPECT_NEAR(closest_outline_point(cut, {x, 40}).distance_mm, 0, 1e-4) << x;
  }
  // Round the corner the cut line goes from 18 mm to 0: it never comes nearer the net than the smaller.
  for (const Point2& p : cut.points) EXPECT_GE(p.y(), -18.0 - 1e-4);
}

// A wedge 6 mm wide at its base with 18 mm on its long bottom edge: a two-sided band would reach over
// the top edge; growing outward leaves the top edge where it is.
TEST(OutwardAllowance, NarrowWedgeKeepsItsOtherEdge) {
  Polygon2 net;
  net.points = {{0, 0}, {120, 0}, {0, 6}};
  const std::vector<AllowanceEdge> edges = {{{{0, 0}, {120, 0}}, 18}, {{{120, 0}, {0, 6}}, 0}, {{{0, 6}, {0, 0}}, 0}};
  const Polygon2 cut = grow_outward_by_allowances(net, edges, 0.02);
  for (const double t : {0.2, 0.5, 0.8}) {
    const Point2 on_top = (1 - t) * Point2(120, 0) + t * Point2(0, 6);
    EXPECT_NEAR(closest_outline_point(cut, on_top).distance_mm, 0, 1e-4) << t;
    EXPECT_NEAR(ray_to_outline(cut, {120 * t, 0}, {0, -1}), 18, 1e-4) << t;
  }
}

// A lasting edge (18 mm) running on into an underlay (8 mm), the outline almost straight through the
// corner where they meet (a style line meeting the feather line at a shallow angle): the cut line keeps
// 18 mm up to the corner and comes down at 45 degrees on the underlay's side, whatever the few degrees
// the outline turns there; an edge of 0 after it stays where it is.
TEST(OutwardAllowance, AChangeOfAllowanceIsAChamferOnTheSmallerSide) {
  for (const double turn_deg : {-3.0, 0.0, 3.0}) {
    // Bottom edge from x = 0 to 100 (18 mm), then on from x = 100 to 200 (8 mm) turned by turn_deg, up
    // and back along the top (0).
    const double turn = turn_deg * M_PI / 180;
    const Point2 corner{100, 0}, end = corner + 100 * Point2(std::cos(turn), std::sin(turn));
    Polygon2 net;
    net.points = {{0, 0}, corner, end, {end.x(), 60}, {0, 60}};
    const std::vector<AllowanceEdge> edges = {{{{0, 0}, corner}, 18}, {{corner, end}, 8},
                                              {{end, {end.x(), 60}, {0, 60}, {0, 0}}, 0}};
    const Polygon2 cut = grow_outward_by_allowances(net, edges, 0.02);
    const std::string where = "turn " + std::to_string(turn_deg) + " deg";
    const Point2 down = Point2(std::sin(turn), -std::cos(turn));  // the underlay's outward normal
    EXPECT_NEAR(ray_to_outline(cut, {99, 0}, {0, -1}), 18, 1e-3) << where << ": the lasting margin up to the corner";
    for (const double along : {2.0, 5.0, 8.0}) {
      // 45 degrees: the height falls by 1 mm per mm along; the ray meets the slope a little nearer.
      const double height = ray_to_outline(cut, corner + along * Point2(std::cos(turn), std::sin(turn)), down);
      EXPECT_NEAR(height, 18 - along, 0.05) << where << " at " << along << " mm";
    }
    for (const double along : {11.0, 50.0, 90.0}) {
      EXPECT_NEAR(ray_to_outline(cut, corner + along * Point2(std::cos(turn), std::sin(turn)), down), 8, 1e-3) << where;
    }
    EXPECT_NEAR(closest_outline_point(cut, {50, 60}).distance_mm, 0, 1e-4) << where;
  }
  // To 0 (a raw edge over its neighbour): that edge stays exactly in place, the step is square.
  Polygon2 net;
  net.points = {{0, 0}, {100, 0}, {200, 0}, {200, 60}, {0, 60}};
  const Polygon2 cut = grow_outward_by_allowances(
      net, {{{{0, 0}, {100, 0}}, 18}, {{{100, 0}, {200, 0}}, 0}, {{{200, 0}, {200, 60}, {0, 60}, {0, 0}}, 0}}, 0.02);
  for (const double x : {101.0, 105.0, 150.0}) EXPECT_NEAR(closest_outline_point(cut, {x, 0}).distance_mm, 0, 1e-4) << x;
}

// A raw edge (0) meeting an 18 mm lasting edge at a sharp corner (the outline turns 120 degrees): the
// raw edge's line runs on straight through the lasting margin, as a pattern maker extends it, and the
// margin's corner is rounded at 18 mm up to that line; nothing bulges past it.
TEST(OutwardAllowance, ARawEdgesLineRunsOnThroughItsNeighboursAllowance) {
  const Point2 corner{100, 0}, raw_direction{-0.5, std::sqrt(3.0) / 2};  // the raw edge leaves the corner at 120 degrees
  Polygon2 net;
  net.points = {{0, 0}, corner, corner + 50 * raw_direction, {0, 50 * raw_direction.y()}};
  const std::vector<AllowanceEdge> edges = {{{{0, 0}, corner}, 18},
                                            {{corner, corner + 50 * raw_direction}, 0},
                                            {{corner + 50 * raw_direction, {0, 50 * raw_direction.y()}, {0, 0}}, 0}};
  const Polygon2 cut = grow_outward_by_allowances(net, edges, 0.02);
  for (const double along : {5.0, 10.0, 17.9}) {  // the raw edge's line, past the corner
    EXPECT_NEAR(closest_outline_point(cut, corner - along * raw_direction).distance_mm, 0, 1e-3) << along;
  }
  const Point2 between = (Point2(0, -1) - raw_direction).normalized();  // between the square end and that line
  EXPECT_NEAR(closest_outline_point(cut, corner + 18 * between).distance_mm, 0, 0.02) << "rounded at 18 mm";
  EXPECT_NEAR(ray_to_outline(cut, {95, 0}, {0, -1}), 18, 1e-3) << "the lasting margin up to the corner";
  EXPECT_NEAR(ray_to_outline(cut, {105, 0}, {0, -1}), 5 * std::tan(60 * M_PI / 180), 1e-3) << "past it, the raw edge's line";
  // Nothing of the cut lies past the raw edge's line, nor further than 18 mm from the corner round it.
  for (const Point2& p : cut.points) {
    const Point2 from = p - corner;
    EXPECT_LE(from.x() * raw_direction.y() - from.y() * raw_direction.x(), 1e-3) << p.transpose();
    if (p.x() > corner.x()) {
      EXPECT_LE(from.norm(), 18 + 1e-3) << p.transpose();
    }
  }
}

TEST(OutwardAllowance, NegativeAllowanceIsRefused) {
  Polygon2 net;
  net.points = {{0, 0}, {10, 0}, {0, 10}};
  try {
    grow_outward_by_allowances(net, {{{{0, 0}, {10, 0}}, -1}, {{{10, 0}, {0, 10}, {0, 0}}, 0}}, 0.02);
    FAIL() << "no error";
  } catch (const EngineError& error) {
    EXPECT_STREQ(error.what(), "every edge allowance must be a finite number of millimetres >= 0");
  }
}

}  // namespace
}  // namespace lastcut
