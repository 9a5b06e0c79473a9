// The toe region of a shoe mold (MoldNestSpec::toe_region_*): on a generated shoe-like outline with
// toe and heel notches, the region is exactly the part of the outline within the fraction of the
// toe-heel length from the toe, for the mold and for its mirrored twin. The reference clips the
// outline against the half plane here with Sutherland-Hodgman, independent of the engine's Clipper use.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/core/engine_error.hpp"
#include "engine/nest/mold_items.hpp"

namespace lastcut {
namespace {

// A shoe-like convex outline: 60 points of a superellipse 260 x 100 mm, toe at +x, heel at -x, tilted.
Mold generated_mold(double tilt_deg) {
  Mold mold;
  mold.name = "vamp";
  const double t = tilt_deg * std::numbers::pi / 180;
  auto turn = [t](double x, double y) { return Point2(std::cos(t) * x - std::sin(t) * y + 40, std::sin(t) * x + std::cos(t) * y + 15); };
  for (int k = 0; k < 60; ++k) {
    const double a = 2 * std::numbers::pi * k / 60;
    const double c = std::cos(a), s = std::sin(a);
    const double x = 130 * std::copysign(std::pow(std::abs(c), 0.7), c), y = 50 * std::copysign(std::pow(std::abs(s), 0.7), s);
    mold.outline.points.push_back(turn(x, y));
  }
  mold.marks.push_back({"toe", turn(130, 0), Point2(-1, 0)});
  mold.marks.push_back({"heel", turn(-130, 0), Point2(1, 0)});
  return mold;
}

// The part of a convex polygon where (p - origin) . direction >= 0 (Sutherland-Hodgman, one plane).
std::vector<Point2> clip_half_plane(const std::vector<Point2>& ring, const Point2& origin, const Point2& direction) {
  std::vector<Point2> out;
  for (size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % n];
    const double da = (a - origin).dot(direction), db = (b - origin).dot(direction);
    if (da >= 0) out.push_back(a);
    if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

double area(const std::vector<Point2>& ring) { return std::abs(signed_area(Polygon2{ring})); }

TEST(NestMoldRegion, ToeRegionIsThePartNearTheToeForMoldAndTwin) {
  const Mold mold = generated_mold(20);
  MoldNestSpec spec;
  spec.mirrored_twins = true;
  spec.toe_region_min_quality = 3;
  spec.toe_region_fraction = 0.35;
  const std::vector<NestItem> items = items_from_molds({mold}, spec);
  ASSERT_EQ(items.size(), 2u);
  for (const NestItem& item : items) {
    ASSERT_EQ(item.quality_regions.size(), 1u);
    const QualityRegion& region = item.quality_regions[0];
    EXPECT_EQ(region.min_quality, 3);
    Point2 toe = Point2::Zero(), heel = Point2::Zero();
    for (const ItemMark& m : item.marks) (m.name == "toe" ? toe : heel) = m.from_mm;
    const Point2 u = (toe - heel).normalized();
    const double length = (toe - heel).norm();
    EXPECT_NEAR(length, 260, 1e-9);
    const std::vector<Point2> expected = clip_half_plane(item.shape.points, toe - 0.35 * length * u, u);
    EXPECT_NEAR(area(region.shape.points), area(expected), 1e-6 * area(expected));
    // Every region point lies within 0.35 x length of the toe along the axis (Clipper rounding aside).
    for (const Point2& p : region.shape.points) EXPECT_GE((p - toe).dot(u), -0.35 * length - 1e-6);
    EXPECT_GT(signed_area(region.shape), 0);  // counter-clockwise
  }
}

TEST(NestMoldRegion, NoRegionWithoutTheSettingOrTheNotches) {
  Mold mold = generated_mold(0);
  MoldNestSpec spec;
  EXPECT_TRUE(items_from_molds({mold}, spec)[0].quality_regions.empty());
  spec.toe_region_min_quality = 2;
  mold.marks.pop_back();  // no heel notch: no axis
  EXPECT_TRUE(items_from_molds({mold}, spec)[0].quality_regions.empty());
  spec.toe_region_fraction = 1.5;
  EXPECT_THROW(items_from_molds({mold}, spec), EngineError);
}

}  // namespace
}  // namespace lastcut
