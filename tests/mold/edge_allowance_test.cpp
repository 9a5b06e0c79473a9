// Per-edge allowances and balance notches on a mold-like patch whose edges are known: every
// distance is measured here from the patch's own rim (point to polyline), not with the engine's
// geometry, so a wrong offset, a wrong edge or a misplaced notch fails.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "engine/core/engine_error.hpp"
#include "engine/mold/mold.hpp"
#include "tests/mold/synthetic_patch.hpp"

namespace lastcut {
namespace {

using test::mold_like_patch;
using test::mold_rim_vertex;

// Simplification tolerance 0.02 mm + Clipper's chord error (half the tolerance) + rounding.
constexpr double kDistanceTolerance_mm = 0.035;

double distance_to_segment_mm(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  const double length_squared = ab.squaredNorm();
  const double t = length_squared > 0.0 ? std::clamp((p - a).dot(ab) / length_squared, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

double distance_to_polyline_mm(const Point2& p, const std::vector<Point2>& line, bool closed = false) {
  double best = std::numeric_limits<double>::infinity();
  const size_t n = line.size();
  for (size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i) best = std::min(best, distance_to_segment_mm(p, line[i], line[(i + 1) % n]));
  return best;
}

struct KnownEdge {
  std::string name;
  double from_deg, to_deg;  // counter-clockwise along the rim
  double allowance_mm;
  std::vector<Point2> rim;  // the patch's rim vertices on this edge, in order
};

struct KnownMold {
  test::FlatPatch patch = mold_like_patch();
  std::map<std::string, int> landmarks;
  std::vector<KnownEdge> edges;
  Point2 rim_point(double degrees) const { return patch.UV.row(mold_rim_vertex(patch, degrees)).transpose(); }
};

KnownMold known_mold(const EdgeAllowances& allowances) {
  KnownMold s;
  s.landmarks = {{"top_front", mold_rim_vertex(s.patch, 50)},
                 {"top_back", mold_rim_vertex(s.patch, 150)},
                 {"heel", mold_rim_vertex(s.patch, 195)},
                 {"toe", mold_rim_vertex(s.patch, 345)}};
  s.edges = {{"top", 50, 150, allowances.top_mm, {}},
             {"back seam", 150, 195, allowances.seam_mm, {}},
             {"feather", 195, 345, allowances.lasting_mm, {}},
             {"front seam", 345, 410, allowances.seam_mm, {}}};
  for (auto& edge : s.edges) {
    const int first = static_cast<int>(std::lround(edge.from_deg / 360.0 * s.patch.rim_count));
    const int last = static_cast<int>(std::lround(edge.to_deg / 360.0 * s.patch.rim_count));
    for (int k = first; k <= last; ++k) edge.rim.push_back(s.patch.UV.row(s.patch.rim_first + k % s.patch.rim_count).transpose());
  }
  return s;
}

Mold mold_of(const KnownMold& s, const EdgeAllowances& allowances, const BalanceNotches& notches = {}) {
  MoldOptions options;
  options.edge_allowances = allowances;
  options.balance_notches = notches;
  return make_mold("medial", s.patch.UV, s.patch.F, s.landmarks, options);
}

// Within the fillet zone of a transition (3 x the larger allowance of the two edges meeting there).
bool in_transition(const KnownMold& s, const EdgeAllowances& a, const Point2& q) {
  const std::map<std::string, double> zone_mm = {{"top_front", 3 * std::max(a.seam_mm, a.top_mm)},
                                                 {"top_back", 3 * std::max(a.seam_mm, a.top_mm)},
                                                 {"heel", 3 * std::max(a.seam_mm, a.lasting_mm)},
                                                 {"toe", 3 * std::max(a.seam_mm, a.lasting_mm)}};
  for (const auto& [name, vertex] : s.landmarks)
    if ((q - Point2(s.patch.UV.row(vertex).transpose())).norm() < zone_mm.at(name) + 1.0) return true;
  return false;
}

double turning_deg(const std::vector<Point2>& q, size_t i) {
  const size_t n = q.size();
  const Point2 a = q[i] - q[(i + n - 1) % n], b = q[(i + 1) % n] - q[i];
  return std::abs(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b))) * 180.0 / std::numbers::pi;
}

// Brute force: any two non-adjacent edges that cross or touch.
bool self_intersects(const std::vector<Point2>& q) {
  const size_t n = q.size();
  auto orient = [](const Point2& a, const Point2& b, const Point2& c) {
    const double v = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    return (v > 0) - (v < 0);
  };
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      const Point2 &a = q[i], &b = q[(i + 1) % n], &c = q[j], &d = q[(j + 1) % n];
      if (orient(a, b, c) * orient(a, b, d) <= 0 && orient(c, d, a) * orient(c, d, b) <= 0 &&
          std::max(a.x(), b.x()) >= std::min(c.x(), d.x()) && std::max(c.x(), d.x()) >= std::min(a.x(), b.x()) &&
          std::max(a.y(), b.y()) >= std::min(c.y(), d.y()) && std::max(c.y(), d.y()) >= std::min(a.y(), b.y()))
        return true;
    }
  return false;
}

TEST(EdgeAllowance, EveryEdgeOfTheCutOutlineLiesItsOwnAllowanceFromTheNetEdge) {
  for (const EdgeAllowances allowances : {EdgeAllowances{15, 5, 0}, EdgeAllowances{18, 3, 2}}) {
    SCOPED_TRACE("lasting " + std::to_string(allowances.lasting_mm) + " seam " + std::to_string(allowances.seam_mm));
    const KnownMold s = known_mold(allowances);
    const Mold mold = mold_of(s, allowances);
    ASSERT_FALSE(mold.net.points.empty());
    std::map<std::string, int> outline_points_on;
    for (const Point2& q : mold.outline.points) {
      if (in_transition(s, allowances, q)) continue;
      const KnownEdge* nearest = nullptr;
      double nearest_mm = std::numeric_limits<double>::infinity();
      for (const auto& edge : s.edges)
        if (const double d = distance_to_polyline_mm(q, edge.rim); d < nearest_mm) nearest_mm = d, nearest = &edge;
      ASSERT_NEAR(nearest_mm, nearest->allowance_mm, kDistanceTolerance_mm) << nearest->name << " at " << q.transpose();
      ++outline_points_on[nearest->name];
    }
    // And the other way round: each net point is its edge's allowance inside the cut outline.
    for (const auto& edge : s.edges) {
      EXPECT_GT(outline_points_on[edge.name], 10) << edge.name;
      for (const Point2& p : edge.rim) {
        if (in_transition(s, allowances, p)) continue;
        ASSERT_NEAR(distance_to_polyline_mm(p, mold.outline.points, true), edge.allowance_mm, kDistanceTolerance_mm)
            << edge.name;
        ASSERT_TRUE(test::inside(mold.outline, p) || edge.allowance_mm == 0.0) << edge.name;
      }
    }
    // The net line kept in the mold is the rim within the simplification tolerance.
    for (const auto& edge : s.edges)
      for (const Point2& p : edge.rim) ASSERT_LE(distance_to_polyline_mm(p, mold.net.points, true), 0.02 + 1e-9);
  }
}

TEST(EdgeAllowance, OutlineIsSimpleCounterClockwiseAndTurnsSmoothlyAtTheTransitions) {
  const EdgeAllowances allowances{15, 5, 0};
  const KnownMold s = known_mold(allowances);
  const Mold mold = mold_of(s, allowances);
  EXPECT_FALSE(self_intersects(mold.outline.points));
  EXPECT_GT(signed_area(mold.outline), signed_area(mold.net));
  double area2 = 0.0;
  const auto& q = mold.outline.points;
  for (size_t i = 0; i < q.size(); ++i) area2 += q[i].x() * q[(i + 1) % q.size()].y() - q[(i + 1) % q.size()].x() * q[i].y();
  EXPECT_GT(area2, 0.0);  // counter-clockwise
  // A hard step from 15 to 5 mm (or 5 to 0) would turn 70-90 degrees at one vertex; a fillet
  // turns a few degrees per chord, like the round parts of the offset itself.
  double worst_deg = 0.0, worst_in_transition_deg = 0.0;
  for (size_t i = 0; i < q.size(); ++i) {
    worst_deg = std::max(worst_deg, turning_deg(q, i));
    if (in_transition(s, allowances, q[i])) worst_in_transition_deg = std::max(worst_in_transition_deg, turning_deg(q, i));
  }
  EXPECT_LT(worst_in_transition_deg, 12.0);
  EXPECT_LT(worst_deg, 12.0);
}

TEST(EdgeAllowance, LandmarkNotchesSitOnTheCutOutlineAtTheLandmarksPerpendicularProjection) {
  const EdgeAllowances allowances{15, 5, 0};
  const KnownMold s = known_mold(allowances);
  const Mold mold = mold_of(s, allowances);
  ASSERT_EQ(mold.marks.size(), 4u);
  for (const MoldMark& mark : mold.marks) {
    const Point2 landmark = s.patch.UV.row(s.landmarks.at(mark.name)).transpose();
    EXPECT_LT(distance_to_polyline_mm(mark.position_mm, mold.outline.points, true), 1e-9) << mark.name;
    EXPECT_NEAR((mark.position_mm - landmark).norm(), distance_to_polyline_mm(landmark, mold.outline.points, true), 1e-9)
        << mark.name;
    EXPECT_NEAR(mark.inward_direction.norm(), 1.0, 1e-12);
  }
}

TEST(BalanceNotches, EvenlySpacedAlongTheSeamsAndTheFeatherLineOnTheCutOutline) {
  const EdgeAllowances allowances{15, 5, 0};
  const KnownMold s = known_mold(allowances);
  const BalanceNotches spacing{20.0, 50.0};
  const Mold mold = mold_of(s, allowances, spacing);
  auto length_mm = [](const std::vector<Point2>& line) {
    double sum = 0.0;
    for (size_t i = 1; i < line.size(); ++i) sum += (line[i] - line[i - 1]).norm();
    return sum;
  };
  // k * spacing <= length - spacing / 2, on the net line (the rim within 0.02 mm).
  auto expected_count = [](double length, double step) { return static_cast<int>(std::floor(length / step - 0.5)); };
  std::map<std::string, int> count;
  for (const MoldMark& mark : mold.marks) {
    EXPECT_LT(distance_to_polyline_mm(mark.position_mm, mold.outline.points, true), 1e-9) << mark.name;
    for (const char* prefix : {"balance_seam_front_", "balance_seam_back_", "balance_feather_"})
      if (mark.name.rfind(prefix, 0) == 0) ++count[prefix];
  }
  EXPECT_EQ(count["balance_feather_"], expected_count(length_mm(s.edges[2].rim), 50.0));
  EXPECT_EQ(count["balance_seam_back_"], expected_count(length_mm(s.edges[1].rim), 20.0));
  EXPECT_EQ(count["balance_seam_front_"], expected_count(length_mm(s.edges[3].rim), 20.0));
  EXPECT_GE(count["balance_feather_"], 3);
  // The first feather notch is 50 mm from the heel along the net line, 15 mm out on the cut line.
  for (const MoldMark& mark : mold.marks) {
    if (mark.name != "balance_feather_1") continue;
    std::vector<Point2> from_heel = s.edges[2].rim;
    double walked = 0.0;
    size_t i = 1;
    while (i < from_heel.size() && walked + (from_heel[i] - from_heel[i - 1]).norm() < 50.0) walked += (from_heel[i] - from_heel[i - 1]).norm(), ++i;
    const Point2 on_net = from_heel[i - 1] + (50.0 - walked) * (from_heel[i] - from_heel[i - 1]).normalized();
    EXPECT_NEAR((mark.position_mm - on_net).norm(), 15.0, 0.05);
    EXPECT_NEAR(distance_to_polyline_mm(mark.position_mm, s.edges[2].rim), 15.0, kDistanceTolerance_mm);
  }
}

TEST(EdgeAllowance, RefusesBadOptionsAndLandmarksInOneLine) {
  const KnownMold s = known_mold({});
  auto refusal = [&](const MoldOptions& options, std::map<std::string, int> landmarks) -> std::string {
    try {
      make_mold("medial", s.patch.UV, s.patch.F, landmarks, options);
    } catch (const EngineError& error) {
      return error.what();
    }
    return "accepted";
  };
  MoldOptions both;
  both.allowance_mm = 3;
  both.edge_allowances = EdgeAllowances{15, 5, 0};
  EXPECT_EQ(refusal(both, s.landmarks), "give one allowance for all edges or per-edge allowances, not both");
  MoldOptions negative;
  negative.edge_allowances = EdgeAllowances{-1, 5, 0};
  EXPECT_EQ(refusal(negative, s.landmarks), "every edge allowance must be a finite number of millimetres >= 0");
  MoldOptions not_a_number;
  not_a_number.edge_allowances = EdgeAllowances{15, std::nan(""), 0};
  EXPECT_EQ(refusal(not_a_number, s.landmarks), "every edge allowance must be a finite number of millimetres >= 0");
  MoldOptions fine;
  fine.edge_allowances = EdgeAllowances{15, 5, 0};
  auto missing = s.landmarks;
  missing.erase("top_back");
  EXPECT_EQ(refusal(fine, missing), "mold medial: per-edge allowances need the landmark top_back on the outline");
  auto swapped = s.landmarks;
  std::swap(swapped["heel"], swapped["top_back"]);
  const std::string order = refusal(fine, swapped);
  EXPECT_EQ(order.rfind("mold medial: landmarks ", 0), 0u) << order;
  EXPECT_NE(order.find(" are neighbours on the outline; expected the order toe, heel, top_back, top_front"),
            std::string::npos)
      << order;
  MoldOptions dense;
  dense.balance_notches.seam_spacing_mm = 2;
  EXPECT_EQ(refusal(dense, s.landmarks), "balance notch spacing along the centre cut must be 0 (off) or at least 5 mm");
  EXPECT_EQ(refusal(fine, s.landmarks), "accepted");
}

}  // namespace
}  // namespace lastcut
