// Style lines taken from a reference last to another (issue 34, "Identity" and "Scale"): the oracle is
// the geometry itself, not the transfer. The lines are plane sections of the reference last made here; the
// same last remeshed and posed, or scaled, has a known true place for every one of them (the section
// moved by the same pose and scale), and each transferred point is measured against that true line.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/style_transfer.hpp"
#include "tests/support/style_line_geometry.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

using test::distance_to_polyline;
using test::plane_section_through;
using test::Polyline;

Polyline moved(const Polyline& line, const Eigen::Affine3d& motion) {
  Polyline out;
  for (const auto& p : line) out.push_back(motion * p);
  return out;
}

ScanResult segmented(const TriMesh& mesh, const std::filesystem::path& file) {
  write_mesh(file, mesh);
  ScanOptions options;
  options.side = FootSide::Right;
  return scan_to_molds(file, options);
}

LastParams right_last(int triangles) {
  LastParams params = LastParams::for_eu_size(42, FootSide::Right);
  params.target_triangles = triangles;
  return params;
}

// Style lines on the reference (generator frame): a vamp line across the instep through both halves
// and the front seam, ending on the feather line; a quarter line around the last at 50 mm through both
// seams; and a cross line at 60 mm from the heel from the feather line to the top edge on both sides.
std::vector<Polyline> style_lines(const TriMesh& reference) {
  return {plane_section_through(reference, {1, 0, 0.35}, {170, 0, 40}), plane_section_through(reference, {0, 0, 1}, {0, 0, 50}),
          plane_section_through(reference, {1, 0, 0}, {60, 0, 0})};
}

// Every outline of the new last's halves as polylines in its scan's frame.
std::vector<Polyline> half_outlines(const ScanResult& scan) {
  std::vector<Polyline> outlines;
  for (const SegmentResult& half : scan.segments)
    for (const std::vector<int>& loop : half.topology.boundary_loops) {
      Polyline outline;
      for (const int v : loop) outline.push_back(scan.scan_to_canonical.inverse() * Eigen::Vector3d(half.mesh3d.V.row(v)));
      outline.push_back(outline.front());
      outlines.push_back(std::move(outline));
    }
  return outlines;
}

struct Deviation {
  double worst_mm = 0, worst_inside_mm = 0;
  double worst_off_edge_mm = 0;  // of the points on an edge, from the new last's own outline
  int points = 0, on_outline = 0, on_seam = 0, medial = 0, lateral = 0;
  double worst_seam_gap_mm = 0;  // between the two points of one seam crossing
};

// Every transferred point of every line against the line's true place on the new last.
Deviation transfer_deviation(const StyleTransfer& transfer, const std::vector<Polyline>& lines,
                             const std::vector<Polyline>& truth, const ScanResult& target) {
  const std::vector<Polyline> outlines = half_outlines(target);
  Deviation deviation;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const TransferredCurve curve = transfer.transfer_curve(lines[i]);
    for (std::size_t k = 0; k < curve.points.size(); ++k) {
      const TransferredPoint& point = curve.points[k];
      const bool seam = point.on_outline && (point.edge == EdgeKind::FrontSeam || point.edge == EdgeKind::BackSeam);
      deviation.on_seam += seam ? 1 : 0;
      if (seam && k + 1 < curve.points.size() && curve.points[k + 1].half != point.half)
        deviation.worst_seam_gap_mm =
            std::max(deviation.worst_seam_gap_mm, (curve.points[k + 1].position_mm - point.position_mm).norm());
      const double off_mm = distance_to_polyline(point.position_mm, truth[i]);
      deviation.worst_mm = std::max(deviation.worst_mm, off_mm);
      if (!point.on_outline) deviation.worst_inside_mm = std::max(deviation.worst_inside_mm, off_mm);
      if (point.on_outline) {
        double off_edge_mm = INFINITY;
        for (const Polyline& outline : outlines) off_edge_mm = std::min(off_edge_mm, distance_to_polyline(point.position_mm, outline));
        deviation.worst_off_edge_mm = std::max(deviation.worst_off_edge_mm, off_edge_mm);
      }
      ++deviation.points;
      deviation.on_outline += point.on_outline ? 1 : 0;
      (point.half == "medial" ? deviation.medial : deviation.lateral) += 1;
    }
  }
  return deviation;
}

class StyleTransferTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    reference_mesh_ = new TriMesh(generate_last(right_last(60000)).mesh);
    reference_ = new ScanResult(segmented(*reference_mesh_, dir_ / "reference.stl"));
  }
  static void TearDownTestSuite() {
    delete reference_;
    delete reference_mesh_;
  }
  static inline test::TempDir dir_{"style-transfer"};
  static inline TriMesh* reference_mesh_ = nullptr;
  static inline ScanResult* reference_ = nullptr;
};

TEST_F(StyleTransferTest, SameLastRemeshedAndPosedKeepsEveryLineWithin0_3mm) {
  LastParams params = right_last(80000);
  params.random_pose = true;
  params.seed = 7;
  const GeneratedLast posed = generate_last(params);
  const ScanResult target = segmented(posed.mesh, dir_ / "posed.stl");
  const StyleTransfer transfer(*reference_, target);
  EXPECT_EQ(transfer.folded_triangles(), 0);

  const std::vector<Polyline> lines = style_lines(*reference_mesh_);
  std::vector<Polyline> truth;
  for (const Polyline& line : lines) truth.push_back(moved(line, posed.canonical_to_scan));
  const Deviation deviation = transfer_deviation(transfer, lines, truth, target);
  std::printf("remeshed and posed: %d points (%d medial, %d lateral, %d on the outline), worst %.3f mm, %.3f mm off the outline\n",
              deviation.points, deviation.medial, deviation.lateral, deviation.on_outline, deviation.worst_mm,
              deviation.worst_inside_mm);
  EXPECT_GT(deviation.medial, 100);
  EXPECT_GT(deviation.lateral, 100);
  // The vamp line crosses the feather line twice, the cross line the feather line and the top edge on
  // both sides; the quarter line stays on the upper. The vamp line crosses the front seam, the quarter
  // line both seams: each crossing comes once per half, at one 3D point.
  EXPECT_EQ(deviation.on_outline - deviation.on_seam, 6);
  EXPECT_EQ(deviation.on_seam, 6);
  EXPECT_LE(deviation.worst_seam_gap_mm, 1e-9);
  EXPECT_LE(deviation.worst_off_edge_mm, 1e-6);  // exactly on the new last's feather line or top edge
  EXPECT_LE(deviation.worst_mm, 0.3);
}

TEST_F(StyleTransferTest, ScaledLastKeepsEveryLineWithin0_3mmPlus0_3Percent) {
  for (const double scale : {1.1, 0.9}) {
    const Eigen::Affine3d pose = Eigen::Translation3d(40, -25, 310) *
                                 Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, -1, 0.4).normalized()) *
                                 Eigen::Scaling(scale, scale, scale);
    TriMesh scaled = *reference_mesh_;
    for (Eigen::Index v = 0; v < scaled.V.rows(); ++v) scaled.V.row(v) = (pose * Eigen::Vector3d(scaled.V.row(v))).transpose();
    const ScanResult target = segmented(scaled, dir_ / "scaled.stl");
    const StyleTransfer transfer(*reference_, target);
    EXPECT_EQ(transfer.folded_triangles(), 0);

    const std::vector<Polyline> lines = style_lines(*reference_mesh_);
    std::vector<Polyline> truth;
    for (const Polyline& line : lines) truth.push_back(moved(line, pose));
    const Deviation deviation = transfer_deviation(transfer, lines, truth, target);
    EXPECT_EQ(deviation.on_outline, 12);
    EXPECT_LE(deviation.worst_off_edge_mm, 1e-6);
    const double limit_mm = 0.3 + 0.003 * 270 * scale;
    std::printf("scale %.1f: %d points, worst %.3f mm (limit %.3f)\n", scale, deviation.points, deviation.worst_mm, limit_mm);
    EXPECT_GT(deviation.points, 200);
    EXPECT_LE(deviation.worst_mm, limit_mm) << "scale " << scale;
  }
}

}  // namespace
}  // namespace lastcut
