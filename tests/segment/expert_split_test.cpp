// The expert's lengthwise plane (engine/segment/expert_split_plane.hpp): on circles, where the second
// toe point, the heel middle and the top centre have closed forms, and on generated lasts, where the
// points are checked against the rule by independent scans of the feather line and the plane is
// followed through the cut to two valid halves.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/lastgen/generate_last.hpp"
#include "engine/segment/expert_split_plane.hpp"
#include "engine/segment/segment_last.hpp"

#include "tests/segment/foot_side_param_name.hpp"

namespace lastcut {
namespace {

using test::side_name;

// A closed circle of `count` points, radius r (mm) about (cx, 0, z), starting at `phase_rad`.
std::vector<Eigen::Vector3d> circle(double cx, double z, double r, int count, double phase_rad) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i) {
    const double angle = phase_rad + 2.0 * std::numbers::pi * i / count;
    points.emplace_back(cx + r * std::cos(angle), r * std::sin(angle), z);
  }
  return points;
}

double plane_distance(const SplitPlane& plane, const Eigen::Vector3d& p) { return plane.normal.dot(p) + plane.offset; }

// Distance (mm) from p to the closed polyline.
double distance_to_loop(const std::vector<Eigen::Vector3d>& loop, const Eigen::Vector3d& p) {
  double best = INFINITY;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector3d a = loop[i], b = loop[(i + 1) % loop.size()];
    const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + t * (b - a) - p).norm());
  }
  return best;
}

TEST(ExpertSplit, PointsOnCirclesHaveTheirClosedForms) {
  // Feather line: circle of radius 100 about (100, 0, 0), x from 0 (heel) to 200 (toe). Section at
  // 0.9 x 200 = 180 mm crosses it at y = +-100 sqrt(1 - 0.8^2) = +-60 mm.
  const double r = 100.0;
  for (FootSide side : {FootSide::Left, FootSide::Right}) {
    const std::vector<Eigen::Vector3d> lower = circle(r, 0.0, r, 7200, 0.013);
    const std::vector<Eigen::Vector3d> upper = circle(90.0, 120.0, 30.0, 3600, 0.0);
    ExpertSplitOptions options;
    const SplitPlane plane = expert_split_plane(lower, upper, options, side);
    const double medial = medial_y_sign(side);
    // Second toe: y2 = y_m + (y_l - y_m) / 3 with y_m = 60 medial, y_l = 60 lateral: 20 mm medial.
    const double y_toe = medial * (60.0 - 120.0 / 3.0);
    const Eigen::Vector3d toe(r + std::sqrt(r * r - y_toe * y_toe), y_toe, 0.0);
    EXPECT_LT((plane.T2 - toe).norm(), 1e-3) << plane.T2.transpose();
    // Heel middle: on a circle, the farthest point from T2 is the antipode through the centre, and
    // the arc around it is symmetric about it.
    const Eigen::Vector3d centre(r, 0.0, 0.0);
    const Eigen::Vector3d heel = centre - r * (toe - centre).normalized();
    EXPECT_LT((plane.T3 - heel).norm(), 1e-3) << plane.T3.transpose();
    EXPECT_LT((plane.T1 - Eigen::Vector3d(90.0, 0.0, 120.0)).norm(), 1e-9);
    for (const Eigen::Vector3d& p : {plane.T1, plane.T2, plane.T3}) EXPECT_LT(std::abs(plane_distance(plane, p)), 1e-9);
    EXPECT_NEAR(plane.normal.norm(), 1.0, 1e-12);
    EXPECT_GT(plane.normal.y() * medial, 0.0);
  }
}

class ExpertSplitOnLasts : public testing::TestWithParam<FootSide> {};

TEST_P(ExpertSplitOnLasts, PointsLieWhereTheRuleSaysAndTheHalvesAreValid) {
  const FootSide side = GetParam();
  LastParams params = LastParams::for_eu_size(side == FootSide::Left ? 38 : 44, side);
  params.target_triangles = 30000;
  // Generated lasts are in the canonical frame already: no orientation step.
  const OrientedLast last{generate_last(params).mesh, Eigen::Affine3d::Identity(), side, {}};
  SegmentOptions options;
  options.split_rule = SplitRule::Expert;
  const BandCut band = cut_band(last, options);
  const SplitPlane plane = place_split_plane(band, options);
  const std::vector<Eigen::Vector3d>& lower = band.lower_loop;
  for (const Eigen::Vector3d& p : {plane.T1, plane.T2, plane.T3}) EXPECT_LT(std::abs(plane_distance(plane, p)), 1e-9);
  EXPECT_LT(distance_to_loop(lower, plane.T2), 1e-9);
  EXPECT_LT(distance_to_loop(lower, plane.T3), 1e-9);

  // The toe box at 90 % of the feather line's length, scanned here edge by edge.
  double x_back = INFINITY, x_front = -INFINITY;
  for (const Eigen::Vector3d& p : lower) {
    x_back = std::min(x_back, p.x());
    x_front = std::max(x_front, p.x());
  }
  const double x_section = x_back + 0.9 * (x_front - x_back), medial = medial_y_sign(side);
  double y_medial = -INFINITY * medial, y_lateral = INFINITY * medial;
  for (std::size_t i = 0; i < lower.size(); ++i) {
    const Eigen::Vector3d a = lower[i], b = lower[(i + 1) % lower.size()];
    if ((a.x() - x_section) * (b.x() - x_section) > 0.0 || a.x() == b.x()) continue;
    const double y = a.y() + (b.y() - a.y()) * (x_section - a.x()) / (b.x() - a.x());
    if (medial * y > medial * y_medial) y_medial = y;
    if (medial * y < medial * y_lateral) y_lateral = y;
  }
  EXPECT_NEAR((plane.T2.y() - y_medial) / (y_lateral - y_medial), 1.0 / 3.0, 1e-9);
  EXPECT_GT(plane.T2.x(), x_front - 15.0);  // at the toe's front, not on the toe box's side
  // The heel middle is the back-most feather point within 0.5 mm (the heel is round).
  EXPECT_LT(plane.T3.x() - x_back, 0.5);
  // ... and the middle of the heel arc: the feather line sampled every ~0.02 mm, the run of samples
  // around the farthest one from T2 that stays within 2 mm of that distance, T3 at half its length.
  std::vector<Eigen::Vector3d> fine;
  for (std::size_t i = 0; i < lower.size(); ++i)
    for (int s = 0; s < 100; ++s) fine.push_back(lower[i] + (lower[(i + 1) % lower.size()] - lower[i]) * (s / 100.0));
  const std::size_t n = fine.size();
  std::size_t far = 0;
  for (std::size_t i = 0; i < n; ++i)
    if ((fine[i] - plane.T2).norm() > (fine[far] - plane.T2).norm()) far = i;
  const double level = (fine[far] - plane.T2).norm() - 2.0;
  std::size_t first = far + n, end = far + n;
  while ((fine[(first - 1) % n] - plane.T2).norm() >= level) --first;
  while ((fine[(end + 1) % n] - plane.T2).norm() >= level) ++end;
  double arc_length = 0.0, to_t3 = 0.0;
  std::size_t nearest_t3 = first;
  for (std::size_t i = first; i <= end; ++i)
    if ((fine[i % n] - plane.T3).norm() < (fine[nearest_t3 % n] - plane.T3).norm()) nearest_t3 = i;
  for (std::size_t i = first; i < end; ++i) {
    const double step = (fine[(i + 1) % n] - fine[i % n]).norm();
    arc_length += step;
    if (i < nearest_t3) to_t3 += step;
  }
  EXPECT_GT(arc_length, 10.0);  // a round heel: the arc is centimetres long
  EXPECT_NEAR(to_t3, 0.5 * arc_length, 0.1) << "arc " << arc_length << " mm";
  EXPECT_LT((fine[nearest_t3 % n] - plane.T3).norm(), 0.05);
  EXPECT_LT((plane.T3 - fine[far]).norm(), 1.5);  // near the farthest point itself (the heel is nearly round)

  // The whole chain cuts two valid halves along that plane, medial on the medial side.
  const Segmentation halves = segment_last(last, options);
  EXPECT_EQ((halves.plane.normal - plane.normal).norm(), 0.0);
  for (const Segment* half : {&halves.medial, &halves.lateral}) {
    EXPECT_GT(half->mesh.triangle_count(), 5000) << half->name;
    EXPECT_EQ(half->landmarks.size(), 4u) << half->name;
  }
  EXPECT_GT(halves.medial.mesh.V.col(1).mean() * medial, halves.lateral.mesh.V.col(1).mean() * medial);
  // The plane differs from the automatic one (otherwise the option would do nothing).
  const SplitPlane automatic = place_split_plane(band, SegmentOptions{});
  EXPECT_GT((automatic.normal - plane.normal).norm(), 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Sides, ExpertSplitOnLasts, testing::Values(FootSide::Left, FootSide::Right),
                         side_name);

}  // namespace
}  // namespace lastcut
