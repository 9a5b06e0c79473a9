// The comparison against references whose answer is known in closed form: the mold itself moved,
// turned and mirrored; a copy grown by 1 mm; a copy with one corner moved 5 mm.
#include <gtest/gtest.h>
#include <polyclipping/clipper.hpp>

#include <cmath>
#include <numbers>

#include "engine/compare/compare_outlines.hpp"
#include "engine/compare/outline_corners.hpp"
#include "tests/compare/synthetic_mold.hpp"

namespace lastcut {
namespace {

// Shoelace formula, written out here so that the test does not share the engine's area code.
double shoelace_mm2(const std::vector<Point2>& p) {
  double twice = 0.0;
  for (size_t i = 0; i < p.size(); ++i) twice += p[i].x() * p[(i + 1) % p.size()].y() - p[(i + 1) % p.size()].x() * p[i].y();
  return std::abs(0.5 * twice);
}

// The outline mirrored (x negated), turned by angle and shifted: the reference as a shop might
// have it (the pattern of the other foot, lying anywhere on the scanner bed).
Mold moved_reference(const Mold& mold, bool mirror, double angle_rad, const Point2& shift) {
  Mold reference;
  reference.name = "reference";
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  for (const auto& p : mold.outline.points) {
    const Point2 q(mirror ? -p.x() : p.x(), p.y());
    reference.outline.points.emplace_back(c * q.x() - s * q.y() + shift.x(), s * q.x() + c * q.y() + shift.y());
  }
  return reference;  // no marks: its corners are found geometrically
}

TEST(CompareAlignment, MoldAgainstItselfMovedTurnedMirrored) {
  const Mold mold = testing::synthetic_mold();
  for (const bool mirror : {false, true}) {
    const Mold reference = moved_reference(mold, mirror, 0.7, Point2(480.0, -215.0));
    const Comparison result = compare_mold(mold, reference);
    EXPECT_EQ(result.alignment.motion.mirrored, mirror);
    EXPECT_GE(result.alignment.overlap_fraction(), 0.99995) << "mirror " << mirror;
    ASSERT_EQ(result.corners.size(), 4u);
    for (const auto& corner : result.corners) {
      EXPECT_LT(corner.margin_mm, 0.01) << corner.name << " mirror " << mirror;
      EXPECT_TRUE(corner.found_sharp_corner) << corner.name;
    }
    EXPECT_LT(result.deviation.hausdorff_mm, 0.01);
    // The motion found puts every reference point back on the mold point it came from.
    for (size_t i = 0; i < mold.outline.points.size(); i += 50)
      EXPECT_LT((result.alignment.motion.apply(reference.outline.points[i]) - mold.outline.points[i]).norm(), 0.01);
  }
}

TEST(CompareAlignment, MirroredReferenceWithoutMirroringFitsWorse) {
  const Mold mold = testing::synthetic_mold();
  const Mold reference = moved_reference(mold, true, -1.2, Point2(30.0, 40.0));
  CompareOptions options;
  options.overlap.allow_mirror = false;
  const Comparison result = compare_mold(mold, reference, options);
  EXPECT_FALSE(result.alignment.motion.mirrored);
  EXPECT_LT(result.alignment.overlap_fraction(), 0.99);
}

TEST(CompareAlignment, OffsetCopyOverlapIsTwoAOverAPlusB) {
  const Mold mold = testing::synthetic_mold();
  // The copy grown by 1 mm with round joins, by Clipper directly (1 unit = 1 um).
  ClipperLib::Path path;
  for (const auto& p : mold.outline.points) path.emplace_back(std::llround(p.x() * 1e3), std::llround(p.y() * 1e3));
  ClipperLib::ClipperOffset offset(2.0, 2.0);  // arc tolerance 2 um
  offset.AddPath(path, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  ClipperLib::Paths grown;
  offset.Execute(grown, 1000.0);
  ASSERT_EQ(grown.size(), 1u);
  Mold reference;
  for (const auto& q : grown.front()) reference.outline.points.emplace_back(q.X * 1e-3 + 100.0, q.Y * 1e-3 - 50.0);

  const double a = shoelace_mm2(mold.outline.points), b = shoelace_mm2(reference.outline.points);
  const double expected_pct = 100.0 * 2.0 * a / (a + b);
  const Comparison result = compare_mold(mold, reference);
  EXPECT_NEAR(100.0 * result.alignment.overlap_fraction(), expected_pct, 0.05);
  EXPECT_NEAR(result.alignment.intersection_area_mm2, a, 1e-3 * a);
  EXPECT_NEAR(result.alignment.reference_area_mm2, b, 1e-6 * b);
  // Every mold corner finds the rounded corner of the copy, 1 mm away from where the mold sits
  // at the most (the mold can shift inside the copy) plus the rounding.
  for (const auto& corner : result.corners) {
    EXPECT_TRUE(corner.found_sharp_corner) << corner.name;
    EXPECT_LT(corner.margin_mm, 3.0) << corner.name;
  }
}

TEST(CompareAlignment, OneCornerMovedFiveMillimetres) {
  const Mold mold = testing::synthetic_mold();
  // The toe corner pulled 5 mm outward along the sole line; the outline within 25 mm of arc
  // length follows it with a linear fall-off, the rest is untouched.
  const Point2 toe = mold.marks[1].position_mm;
  const Point2 pull = 5.0 * Point2(262.0, 12.0).normalized();
  size_t toe_index = 0;
  for (size_t i = 0; i < mold.outline.points.size(); ++i)
    if ((mold.outline.points[i] - toe).norm() < 1e-9) toe_index = i;
  Mold reference;
  const auto& p = mold.outline.points;
  const int n = static_cast<int>(p.size());
  std::vector<double> along(p.size(), 1e9);
  along[toe_index] = 0.0;
  for (int direction : {1, -1}) {
    double length = 0.0;
    for (int k = 1; k < n / 2; ++k) {
      const size_t i = static_cast<size_t>((static_cast<int>(toe_index) + direction * k + n) % n);
      const size_t previous = static_cast<size_t>((static_cast<int>(toe_index) + direction * (k - 1) + n) % n);
      length += (p[i] - p[previous]).norm();
      along[i] = std::min(along[i], length);
    }
  }
  for (size_t i = 0; i < p.size(); ++i)
    reference.outline.points.push_back(p[i] + std::max(0.0, 1.0 - along[i] / 25.0) * pull);

  const Comparison result = compare_mold(mold, reference);
  ASSERT_EQ(result.corners.size(), 4u);
  for (const auto& corner : result.corners) {
    if (corner.name == "toe") {
      EXPECT_NEAR(corner.margin_mm, 5.0, 0.1);
      EXPECT_LT((corner.reference_mm - (toe + pull)).norm(), 0.1);
    } else {
      EXPECT_LT(corner.margin_mm, 0.1) << corner.name;
    }
  }
  EXPECT_NEAR(result.deviation.hausdorff_mm, 5.0, 0.1);
}

TEST(CompareAlignment, SharpCornersOfASquareAreItsVertices) {
  Polygon2 square;
  for (int i = 0; i < 40; ++i) square.points.emplace_back(i, 0);
  for (int i = 0; i < 40; ++i) square.points.emplace_back(40, i);
  for (int i = 0; i < 40; ++i) square.points.emplace_back(40 - i, 40);
  for (int i = 0; i < 40; ++i) square.points.emplace_back(0, 40 - i);
  const auto corners = sharp_corners(square);
  ASSERT_EQ(corners.size(), 4u);
  const Point2 expected[4] = {{0, 0}, {40, 0}, {40, 40}, {0, 40}};
  for (int c = 0; c < 4; ++c) {
    EXPECT_LT((corners[static_cast<size_t>(c)].at_mm - expected[c]).norm(), 1e-9) << c;
    EXPECT_NEAR(corners[static_cast<size_t>(c)].turn_deg, 90.0, 1e-9);
  }
}

}  // namespace
}  // namespace lastcut
