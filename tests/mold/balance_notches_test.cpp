// Balance notches on the two molds of one generated last: the medial and lateral pieces are sewn
// together along the centre cut, so their notches must sit at the same arc lengths on the net line
// from the toe (front cut) and from the heel (back cut). Arc lengths are measured here on each
// mold's own net line, from the toe and heel found on a run without allowance (where the landmark
// notches sit exactly on the landmark vertices; the pipeline is deterministic, so the net lines of
// both runs are the same polygon).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

// Position of p along the closed polygon, counter-clockwise from point 0 (mm), p's projection.
double arc_position_mm(const Polygon2& polygon, const Point2& p, double* distance_mm = nullptr) {
  const auto& q = polygon.points;
  double best = std::numeric_limits<double>::infinity(), best_s = 0.0, walked = 0.0;
  for (size_t i = 0; i < q.size(); ++i) {
    const Point2 a = q[i], ab = q[(i + 1) % q.size()] - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    const double d = (a + t * ab - p).norm();
    if (d < best) best = d, best_s = walked + t * ab.norm();
    walked += ab.norm();
  }
  if (distance_mm) *distance_mm = best;
  return best_s;
}

// First point of the polygon's boundary on the ray from + t * direction, t >= -1e-4 mm.
Point2 first_hit(const Polygon2& polygon, const Point2& from, const Point2& direction) {
  double best_t = std::numeric_limits<double>::infinity();
  const auto& q = polygon.points;
  for (size_t i = 0; i < q.size(); ++i) {
    const Point2 a = q[i], e = q[(i + 1) % q.size()] - a, w = a - from;
    const double det = direction.x() * e.y() - direction.y() * e.x();
    if (det == 0.0) continue;
    const double t = (w.x() * e.y() - w.y() * e.x()) / det;
    const double u = (w.x() * direction.y() - w.y() * direction.x()) / det;
    if (u >= 0.0 && u <= 1.0 && t >= -1e-4) best_t = std::min(best_t, t);
  }
  return from + best_t * direction;
}

const MoldMark& mark_named(const Mold& mold, const std::string& name) {
  for (const MoldMark& mark : mold.marks)
    if (mark.name == name) return mark;
  throw std::runtime_error("no mark " + name);
}

// Arc lengths (mm) of the marks named prefix1, prefix2, ... along the net line, measured from the
// landmark `from` in the direction of the landmark `towards`.
std::vector<double> notch_arc_lengths(const Mold& with_allowance, const Mold& net_run, const std::string& prefix,
                                      const std::string& from, const std::string& towards) {
  const Polygon2& net = net_run.outline;
  const double perimeter_mm = perimeter(net);
  const double s0 = arc_position_mm(net, mark_named(net_run, from).position_mm);
  const double s_towards = arc_position_mm(net, mark_named(net_run, towards).position_mm);
  const bool forward = std::fmod(s_towards - s0 + perimeter_mm, perimeter_mm) < 0.5 * perimeter_mm;
  std::vector<double> lengths;
  for (int k = 1;; ++k) {
    const auto found = std::find_if(with_allowance.marks.begin(), with_allowance.marks.end(),
                                    [&](const MoldMark& m) { return m.name == prefix + std::to_string(k); });
    if (found == with_allowance.marks.end()) break;
    // Where the notch line, continued inward, meets the net line: the stitch point it marks.
    const Point2 hit = first_hit(net, found->position_mm, found->inward_direction);
    double off_mm = 0.0;
    const double s = arc_position_mm(net, hit, &off_mm);
    EXPECT_LT(off_mm, 1e-6);
    lengths.push_back(std::fmod((forward ? s - s0 : s0 - s) + 2 * perimeter_mm, perimeter_mm));
  }
  return lengths;
}

double distance_to_outline_mm(const Polygon2& polygon, const Point2& p) {
  double d = 0.0;
  arc_position_mm(polygon, p, &d);
  return d;
}

TEST(BalanceNotchesOnALast, MedialAndLateralCentreCutNotchesMeetWhenSewn) {
  const lastcut::test::TempDir dir("balance");
  LastParams params = LastParams::for_eu_size(41, FootSide::Left);
  params.target_triangles = 12000;
  write_stl_binary(dir / "last.stl", generate_last(params).mesh);

  ScanOptions net_options;
  net_options.mold.balance_notches = BalanceNotches{20, 50};
  ScanOptions options = net_options;
  options.mold.edge_allowances = EdgeAllowances{16, 5, 0};
  const ScanResult net_run = scan_to_molds(dir / "last.stl", net_options);
  const ScanResult result = scan_to_molds(dir / "last.stl", options);
  ASSERT_EQ(result.segments.size(), 2u);

  std::map<std::string, std::map<std::string, std::vector<double>>> lengths;  // segment -> edge -> arc lengths
  for (size_t i = 0; i < 2; ++i) {
    const Mold& mold = result.segments[i].mold;
    const Mold& net_mold = net_run.segments[i].mold;
    SCOPED_TRACE(mold.name);
    ASSERT_EQ(mold.net.points, net_mold.outline.points);  // the net line is the outline without allowance
    for (const MoldMark& mark : mold.marks) EXPECT_LT(distance_to_outline_mm(mold.outline, mark.position_mm), 1e-9) << mark.name;
    auto& edges = lengths[mold.name];
    edges["front"] = notch_arc_lengths(mold, net_mold, "balance_seam_front_", "toe", "top_front");
    edges["back"] = notch_arc_lengths(mold, net_mold, "balance_seam_back_", "heel", "top_back");
    edges["feather"] = notch_arc_lengths(mold, net_mold, "balance_feather_", "heel", "toe");
    // Each notch is k x spacing along the net line from its landmark.
    for (const auto& [edge, values] : edges) {
      const double spacing_mm = edge == "feather" ? 50.0 : 20.0;
      EXPECT_GE(values.size(), edge == "back" ? 1u : 2u) << edge;
      for (size_t k = 0; k < values.size(); ++k) EXPECT_NEAR(values[k], (k + 1) * spacing_mm, 0.01) << edge << " " << k + 1;
    }
  }
  for (const char* edge : {"front", "back"}) {
    const auto& medial = lengths["medial"][edge];
    const auto& lateral = lengths["lateral"][edge];
    ASSERT_EQ(medial.size(), lateral.size()) << edge;
    for (size_t k = 0; k < medial.size(); ++k) EXPECT_NEAR(medial[k], lateral[k], 0.01) << edge << " " << k + 1;
  }
}

}  // namespace
}  // namespace lastcut
