#pragma once
// The shipped loafer's style lines (config/styles/loafer/lines.obj) and label points, drawn on a
// reference last from its own geometry, so the file can be made again and checked
// (tests/style/loafer_lines_test.cpp; LASTCUT_WRITE_LOAFER_LINES=1 rewrites it).
//
// A moccasin-style loafer, as a pattern maker would draw it on the last:
//  - apron: the plug's seam. Seen from above it is the feather line's outline around the forefoot moved
//    inward (kApronInsetToe_mm at the ball and toe, more towards the instep so the plug narrows), laid
//    on the last straight down (the topmost point of the last under each point of the outline). The
//    loop closes across the instep on the last's top cut: on the upper it is a U from the top edge round
//    the toe back to the top edge, and the plug's throat is the top edge (the upper ends there).
//  - vamp: the vamp's back seam, a plane section leaning forward from the feather line at the waist to
//    the top cut behind the plug; the vamp wraps round the plug between it and the feather line.
//  - counter: the heel counter's line, the derby's plane section round the heel (tests/support/derby_style.hpp).
// Frame: the reference scan's (a generated last: heel at x = 0, toe at +x, ground z = 0, +z up; a right
// last, medial +y).
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/forme_boundary.hpp"
#include "engine/style/style_lines_obj.hpp"
#include "tests/support/style_line_geometry.hpp"

namespace lastcut::test {

inline constexpr double kApronInsetToe_mm = 17;     // the plug's seam inside the feather line, forefoot (plan view)
inline constexpr double kApronInsetThroat_mm = 21;  // ... at the back of the forefoot, where it runs onto the top cut
inline constexpr double kApronFull_x_mm = 160;      // the toe inset holds in front of this
inline constexpr double kApronBack_x_mm = 90;       // the loop closes across the top cut here
inline constexpr double kPlanStep_mm = 1.0;         // the outline is resampled this finely (plan view)

using PlanLine = std::vector<Eigen::Vector2d>;

// The topmost point of the mesh straight above or below (x, y); none when the vertical misses it.
inline std::optional<double> topmost_z(const TriMesh& mesh, const Eigen::Vector2d& xy) {
  std::optional<double> top;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const Eigen::Vector2d ab = (b - a).head<2>(), ac = (c - a).head<2>(), ap = xy - a.head<2>();
    const double det = ab.x() * ac.y() - ab.y() * ac.x();
    if (std::abs(det) < 1e-12) continue;  // a wall seen edge-on from above
    const double u = (ap.x() * ac.y() - ap.y() * ac.x()) / det, v = (ab.x() * ap.y() - ab.y() * ap.x()) / det;
    if (u < 0 || v < 0 || u + v > 1) continue;
    const double z = a.z() + u * (b.z() - a.z()) + v * (c.z() - a.z());
    if (!top || z > *top) top = z;
  }
  return top;
}

inline Polyline laid_on_top(const TriMesh& mesh, const PlanLine& plan) {
  Polyline line;
  for (const Eigen::Vector2d& xy : plan)
    if (const std::optional<double> z = topmost_z(mesh, xy)) line.emplace_back(xy.x(), xy.y(), *z);
  return line;
}

// An open plan line resampled every `step_mm` along its length (its ends kept).
inline PlanLine resampled(const PlanLine& line, double step_mm) {
  PlanLine out{line.front()};
  double carried_mm = 0;
  for (std::size_t i = 1; i < line.size(); ++i) {
    const Eigen::Vector2d d = line[i] - line[i - 1];
    const double length_mm = d.norm();
    double at_mm = step_mm - carried_mm;
    for (; at_mm < length_mm; at_mm += step_mm) out.push_back(line[i - 1] + d * (at_mm / length_mm));
    carried_mm = length_mm - (at_mm - step_mm);
  }
  if ((out.back() - line.back()).norm() > 1e-9) out.push_back(line.back());
  return out;
}

// The feather line of the reference's half `name` in the scan's frame, heel to toe, seen from above.
inline PlanLine feather_plan(const ScanResult& scan, const std::string& name) {
  for (const SegmentResult& half : scan.segments) {
    if (half.name != name) continue;
    const FormeBoundary boundary = forme_boundary(half.mesh3d, half.topology, half.landmarks);
    const Eigen::Affine3d to_scan = scan.scan_to_canonical.inverse();
    PlanLine plan;
    for (const int v : boundary.edge(EdgeKind::Feather).vertices)
      plan.push_back((to_scan * Eigen::Vector3d(half.mesh3d.V.row(v).transpose())).head<2>());
    return plan;
  }
  throw EngineError("the reference last has no " + name + " half");
}

inline double apron_inset_mm(double x_mm) {
  const double t = std::clamp((kApronFull_x_mm - x_mm) / (kApronFull_x_mm - kApronBack_x_mm), 0.0, 1.0);
  return kApronInsetToe_mm + t * (kApronInsetThroat_mm - kApronInsetToe_mm);
}

// The apron's loop seen from above: the forefoot's feather outline (lateral side to the toe, back along
// the medial side) moved inward along its normal, smoothed over +-kNormalSpan points, closed straight
// across at kApronBack_x_mm. Starts and ends on that closing (on the top cut).
inline PlanLine apron_plan(const ScanResult& scan) {
  constexpr int kNormalSpan = 8;
  PlanLine outline;
  for (const Eigen::Vector2d& p : feather_plan(scan, "lateral"))
    if (p.x() >= kApronBack_x_mm) outline.push_back(p);
  PlanLine medial = feather_plan(scan, "medial");
  std::reverse(medial.begin(), medial.end());
  for (const Eigen::Vector2d& p : medial)
    if (p.x() >= kApronBack_x_mm && (p - outline.back()).norm() > 1e-6) outline.push_back(p);
  outline = resampled(outline, kPlanStep_mm);
  // Lateral to medial round the toe: the inside of the outline is to the left on a right last (medial +y)
  // and to the right on a left one.
  const double inside = outline.back().y() > outline.front().y() ? 1.0 : -1.0;
  PlanLine loop;
  const int n = static_cast<int>(outline.size());
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d along = outline[static_cast<std::size_t>(std::min(i + kNormalSpan, n - 1))] -
                                  outline[static_cast<std::size_t>(std::max(i - kNormalSpan, 0))];
    const Eigen::Vector2d normal = inside * Eigen::Vector2d(-along.y(), along.x()).normalized();
    const Eigen::Vector2d& p = outline[static_cast<std::size_t>(i)];
    loop.push_back(p + apron_inset_mm(p.x()) * normal);
  }
  std::erase_if(loop, [](const Eigen::Vector2d& p) { return p.x() < kApronBack_x_mm; });
  loop.insert(loop.begin(), loop.back());  // closing across the top cut, then round the toe back to it
  return resampled(loop, kPlanStep_mm);
}

// The point of the plane section x = x_mm nearest height z_mm on the side `side` (+1: +y, -1: -y).
inline Eigen::Vector3d side_point(const TriMesh& mesh, double x_mm, double z_mm, double side) {
  const Polyline section = plane_section(mesh, Eigen::Vector3d::UnitX(), x_mm);
  double middle_y = 0;
  for (const Eigen::Vector3d& p : section) middle_y += p.y() / static_cast<double>(section.size());
  Eigen::Vector3d best = section.front();
  for (const Eigen::Vector3d& p : section)
    if (side * (p.y() - middle_y) > 0 && std::abs(p.z() - z_mm) < std::abs(best.z() - z_mm)) best = p;
  return best;
}

struct LoaferDrawing {
  std::vector<StyleLine> lines;                                  // apron, vamp, counter
  std::vector<std::pair<std::string, Eigen::Vector3d>> labels;  // one point inside each piece
};

// mesh: the reference last as scanned (generator frame, a right last); scan: it segmented with named halves.
inline LoaferDrawing draw_loafer(const TriMesh& mesh, const ScanResult& scan) {
  LoaferDrawing drawing;
  const PlanLine plan = apron_plan(scan);
  drawing.lines = {{"apron", laid_on_top(mesh, plan)},
                   {"vamp", plane_section_through(mesh, {1, 0, 0.4}, {75, 0, 141})},
                   {"counter", plane_section_through(mesh, {0.45, 0, 1}, {0, 0, 60})}};
  // The plug's middle on the forefoot; the vamp halfway between the feather line and the plug's seam.
  const PlanLine lateral = feather_plan(scan, "lateral");
  const auto at_x = [](const PlanLine& line, double x_mm) {
    return *std::min_element(line.begin(), line.end(), [&](const auto& a, const auto& b) {
      return std::abs(a.x() - x_mm) < std::abs(b.x() - x_mm);
    });
  };
  const PlanLine medial = feather_plan(scan, "medial");
  const Eigen::Vector2d forefoot = (at_x(lateral, 215) + at_x(medial, 215)) / 2;
  const double medial_side = at_x(medial, 70).y() > at_x(lateral, 70).y() ? 1.0 : -1.0;
  const Eigen::Vector2d vamp_side = at_x(lateral, 200) + Eigen::Vector2d(0, medial_side * 0.5 * kApronInsetToe_mm);
  const Polyline heel = plane_section(mesh, Eigen::Vector3d::UnitZ(), 40);
  drawing.labels = {{"apron", laid_on_top(mesh, {forefoot}).front()},
                    {"vamp", laid_on_top(mesh, {vamp_side}).front()},
                    {"medial quarter", side_point(mesh, 70, 50, medial_side)},
                    {"lateral quarter", side_point(mesh, 70, 50, -medial_side)},
                    {"counter", *std::min_element(heel.begin(), heel.end(), [](const auto& a, const auto& b) { return a.x() < b.x(); })}};
  return drawing;
}

}  // namespace lastcut::test
