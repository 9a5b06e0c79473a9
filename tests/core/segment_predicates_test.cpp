// The segment and point predicates (engine/core/segment_predicates.hpp) against independent oracles:
// segments_touch against the parametric intersection solved in exact integer arithmetic (on small
// integer coordinates the doubles are exact too, so both must agree on every pair, and a grid of
// -3..3 is full of collinear, touching and zero-length cases); point_in_ring against the winding
// number summed from angles.
#include "engine/core/segment_predicates.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace lastcut {
namespace {

using I = long long;
struct IPoint {
  I x, y;
};

I cross(IPoint a, IPoint b) { return a.x * b.y - a.y * b.x; }
I dot(IPoint a, IPoint b) { return a.x * b.x + a.y * b.y; }
IPoint minus(IPoint a, IPoint b) { return {a.x - b.x, a.y - b.y}; }

// num / den lies in [0, 1] (den != 0).
bool fraction_in_unit(I num, I den) {
  if (den < 0) num = -num, den = -den;
  return 0 <= num && num <= den;
}

// p lies on the closed segment a-b (a point when a == b).
bool exact_point_on_segment(IPoint p, IPoint a, IPoint b) {
  const IPoint ab = minus(b, a), ap = minus(p, a);
  if (cross(ab, ap) != 0) return false;
  if (dot(ab, ab) == 0) return ap.x == 0 && ap.y == 0;
  return fraction_in_unit(dot(ap, ab), dot(ab, ab));
}

// a + t (b - a) = c + u (d - c) for some t, u in [0, 1].
bool exact_segments_touch(IPoint a, IPoint b, IPoint c, IPoint d) {
  const IPoint r = minus(b, a), s = minus(d, c), qp = minus(c, a);
  const I den = cross(r, s);
  if (den != 0) return fraction_in_unit(cross(qp, s), den) && fraction_in_unit(cross(qp, r), den);
  // Parallel (or a zero-length segment): they share a point iff an end point lies on the other.
  return exact_point_on_segment(a, c, d) || exact_point_on_segment(b, c, d) || exact_point_on_segment(c, a, b) ||
         exact_point_on_segment(d, a, b);
}

Point2 to_point(IPoint p) { return Point2(static_cast<double>(p.x), static_cast<double>(p.y)); }

TEST(SegmentPredicates, AgreesWithExactArithmeticOnEveryKindOfPairOnASmallGrid) {
  std::mt19937 random(11);
  std::uniform_int_distribution<int> coordinate(-3, 3);
  auto point = [&] { return IPoint{coordinate(random), coordinate(random)}; };
  int touching = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    const IPoint a = point(), b = point(), c = point(), d = point();
    const bool expected = exact_segments_touch(a, b, c, d);
    touching += expected;
    ASSERT_EQ(segments_touch(to_point(a), to_point(b), to_point(c), to_point(d)), expected)
        << "(" << a.x << "," << a.y << ")-(" << b.x << "," << b.y << ") and (" << c.x << "," << c.y << ")-(" << d.x
        << "," << d.y << ")";
  }
  // Both answers must be well represented for the comparison to mean anything.
  EXPECT_GT(touching, 20000);
  EXPECT_LT(touching, 180000);
}

TEST(SegmentPredicates, CollinearSegmentsTouchOnlyWhereTheyOverlapOrMeet) {
  const Point2 a(0, 0), b(4, 2);
  EXPECT_TRUE(segments_touch(a, b, Point2(2, 1), Point2(6, 3)));   // overlap
  EXPECT_TRUE(segments_touch(a, b, Point2(4, 2), Point2(8, 4)));   // end to end
  EXPECT_TRUE(segments_touch(a, b, Point2(-2, -1), Point2(6, 3)));  // one covers the other
  EXPECT_FALSE(segments_touch(a, b, Point2(6, 3), Point2(8, 4)));  // a gap on the same line
  EXPECT_FALSE(segments_touch(Point2(0, 5), Point2(0, 9), Point2(0, 0), Point2(0, 4)));  // vertical, gap of 1
}

TEST(SegmentPredicates, AnEndPointOnTheOtherSegmentTouches) {
  EXPECT_TRUE(segments_touch(Point2(0, 0), Point2(10, 0), Point2(5, 0), Point2(5, 7)));   // T junction
  EXPECT_TRUE(segments_touch(Point2(0, 0), Point2(10, 0), Point2(10, 0), Point2(12, 3)));  // shared end point
  EXPECT_FALSE(segments_touch(Point2(0, 0), Point2(10, 0), Point2(5, 0.5), Point2(5, 7)));
  // The gap is the smallest double step above 1: apart, the predicates take no tolerance.
  EXPECT_FALSE(segments_touch(Point2(0, 1), Point2(10, 1), Point2(5, std::nextafter(1.0, 2.0)), Point2(5, 7)));
}

TEST(SegmentPredicates, NearlyParallelSegmentsCrossOnlyWhenTheirEndsSwapSides) {
  // b-a and d-c differ in slope by 1e-9; they cross at x = 5 in the first case and never in the second.
  const double e = 1e-9;
  EXPECT_TRUE(segments_touch(Point2(0, 0), Point2(10, 0), Point2(0, -5 * e), Point2(10, 5 * e)));
  EXPECT_FALSE(segments_touch(Point2(0, 0), Point2(10, 0), Point2(0, 1 * e), Point2(10, 11 * e)));
  // Parallel a millimetre apart, overlapping in x.
  EXPECT_FALSE(segments_touch(Point2(0, 0), Point2(10, 10), Point2(1, 0), Point2(11, 10)));
}

TEST(SegmentPredicates, ZeroLengthSegmentsArePoints) {
  const Point2 p(3, 3);
  EXPECT_TRUE(segments_touch(p, p, Point2(0, 0), Point2(6, 6)));    // on the other segment
  EXPECT_FALSE(segments_touch(p, p, Point2(4, 4), Point2(6, 6)));   // on its line, beyond its end
  EXPECT_FALSE(segments_touch(p, p, Point2(0, 1), Point2(6, 7)));   // beside it
  EXPECT_TRUE(segments_touch(p, p, p, p));
  EXPECT_FALSE(segments_touch(p, p, Point2(3, 4), Point2(3, 4)));
}

TEST(SegmentPredicates, OrientationIsTheSignOfTheTurn) {
  EXPECT_EQ(orientation(Point2(0, 0), Point2(1, 0), Point2(1, 1)), 1);
  EXPECT_EQ(orientation(Point2(0, 0), Point2(1, 1), Point2(1, 0)), -1);
  EXPECT_EQ(orientation(Point2(0, 0), Point2(1, 1), Point2(3, 3)), 0);
  EXPECT_EQ(orientation(Point2(2, 2), Point2(2, 2), Point2(5, 1)), 0);
}

// Winding number of the ring around p, summed from the angles each edge subtends.
int winding_number(const Point2& p, const std::vector<Point2>& ring) {
  double total_rad = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const Point2 u = ring[i] - p, v = ring[(i + 1) % ring.size()] - p;
    total_rad += std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
  }
  return static_cast<int>(std::lround(total_rad / (2 * std::numbers::pi)));
}

TEST(SegmentPredicates, PointInRingAgreesWithTheWindingNumberAwayFromTheBoundary) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> radius(20, 100), coordinate(-110, 110);
  int inside = 0, compared = 0;
  for (int shape = 0; shape < 50; ++shape) {
    // A random star-shaped ring, clockwise every other time: either orientation must work.
    std::vector<Point2> ring;
    const int n = 5 + shape % 20;
    for (int k = 0; k < n; ++k) {
      const double angle = (shape % 2 ? -1 : 1) * 2 * std::numbers::pi * k / n;
      ring.push_back(radius(random) * Point2(std::cos(angle), std::sin(angle)));
    }
    for (int q = 0; q < 400; ++q) {
      const Point2 p(coordinate(random), coordinate(random));
      double clearance_mm = 1e300;
      for (int k = 0; k < n; ++k) clearance_mm = std::min(clearance_mm, distance_to_segment(p, ring[k], ring[(k + 1) % n]));
      if (clearance_mm < 1e-6) continue;
      const bool expected = winding_number(p, ring) != 0;
      inside += expected, ++compared;
      ASSERT_EQ(point_in_ring(p, ring), expected) << "shape " << shape << " point " << p.transpose();
    }
  }
  EXPECT_GT(inside, compared / 10);
  EXPECT_LT(inside, compared - compared / 10);
}

}  // namespace
}  // namespace lastcut
