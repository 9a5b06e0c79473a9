// Style lines taken from a reference last to another (issue 34, "Identity" and "Scale"): the oracle is
// the geometry itself, not the transfer. The lines are plane sections of the reference last made here; the
// same last remeshed and posed, or scaled, has a known true place for every one of them (the section
// moved by the same pose and scale), and each transferred point is measured against that true line.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/style_transfer.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

using Polyline = std::vector<Eigen::Vector3d>;

// The closed loop where the plane {p : normal . p = offset} cuts the mesh, ordered by angle around its
// centroid (the sections used here are star-shaped about it), closed by repeating the first point.
Polyline plane_section(const TriMesh& mesh, const Eigen::Vector3d& normal, double offset) {
  Polyline points;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      if (a > b) continue;  // each edge once (a closed mesh: every edge has both orientations)
      const double da = normal.dot(mesh.V.row(a).transpose()) - offset;
      const double db = normal.dot(mesh.V.row(b).transpose()) - offset;
      if ((da < 0) == (db < 0)) continue;
      const double t = da / (da - db);
      points.push_back((1 - t) * mesh.V.row(a).transpose() + t * mesh.V.row(b).transpose());
    }
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  const Eigen::Vector3d u = normal.unitOrthogonal(), w = normal.cross(u);
  std::sort(points.begin(), points.end(), [&](const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
    return std::atan2((p - centroid).dot(w), (p - centroid).dot(u)) < std::atan2((q - centroid).dot(w), (q - centroid).dot(u));
  });
  points.push_back(points.front());
  return points;
}

double distance_to_polyline(const Eigen::Vector3d& p, const Polyline& line) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < line.size(); ++i) {
    const Eigen::Vector3d ab = line[i] - line[i - 1];
    const double t = std::clamp((p - line[i - 1]).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    best = std::min(best, (line[i - 1] + t * ab - p).norm());
  }
  return best;
}

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
  const auto through = [&](const Eigen::Vector3d& normal, const Eigen::Vector3d& point) {
    return plane_section(reference, normal.normalized(), normal.normalized().dot(point));
  };
  return {through({1, 0, 0.35}, {170, 0, 40}), through({0, 0, 1}, {0, 0, 50}), through({1, 0, 0}, {60, 0, 0})};
}

struct Deviation {
  double worst_mm = 0, worst_inside_mm = 0;
  int points = 0, on_outline = 0, medial = 0, lateral = 0;
};

// Every transferred point of every line against the line's true place on the new last.
Deviation transfer_deviation(const StyleTransfer& transfer, const std::vector<Polyline>& lines,
                             const std::vector<Polyline>& truth) {
  Deviation deviation;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const TransferredCurve curve = transfer.transfer_curve(lines[i]);
    for (const TransferredPoint& point : curve.points) {
      const double off_mm = distance_to_polyline(point.position_mm, truth[i]);
      deviation.worst_mm = std::max(deviation.worst_mm, off_mm);
      if (!point.on_outline) deviation.worst_inside_mm = std::max(deviation.worst_inside_mm, off_mm);
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

TEST_F(StyleTransferTest, SameLastRemeshedAndPosedKeepsLinesWithin0_3mmInsideTheUpper) {
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
  const Deviation deviation = transfer_deviation(transfer, lines, truth);
  std::printf("remeshed and posed: %d points (%d medial, %d lateral, %d on the outline), worst %.3f mm, %.3f mm off the outline\n",
              deviation.points, deviation.medial, deviation.lateral, deviation.on_outline, deviation.worst_mm,
              deviation.worst_inside_mm);
  EXPECT_GT(deviation.medial, 100);
  EXPECT_GT(deviation.lateral, 100);
  EXPECT_GE(deviation.on_outline, 4);  // the lines cross the feather line and the top edge
  EXPECT_LE(deviation.worst_inside_mm, 0.3);
  // A point on an edge lands on the new last's own edge, which its segmentation places independently:
  // between these two meshings of one last the feather line, seams and top edge lie 0.27-0.57 mm apart
  // (measured Nov 29), and the transferred point cannot be nearer the true line than its edge is.
  EXPECT_LE(deviation.worst_mm, 0.6);
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
    const Deviation deviation = transfer_deviation(transfer, lines, truth);
    EXPECT_GE(deviation.on_outline, 4);
    const double limit_mm = 0.3 + 0.003 * 270 * scale;
    std::printf("scale %.1f: %d points, worst %.3f mm (limit %.3f)\n", scale, deviation.points, deviation.worst_mm, limit_mm);
    EXPECT_GT(deviation.points, 200);
    EXPECT_LE(deviation.worst_mm, limit_mm) << "scale " << scale;
  }
}

}  // namespace
}  // namespace lastcut
