// Scans as they come: holes with ragged boundaries are judged by their size across, not by their
// perimeter, and closed up to 30 mm by a patch that continues the surface; a larger hole gets one
// clear refusal. The oracle for "continues the surface" is the generator's own implicit last
// (LastShape), which the scan was made from.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <set>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "engine/core/engine_error.hpp"
#include "engine/core/mesh_topology.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/lastgen/last_shape.hpp"
#include "engine/mesh/fill_holes.hpp"
#include "engine/scan/scan_to_molds.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

struct HoleSpec {
  Eigen::Vector3d near_mm;  // the hole is centred on the vertex nearest this point
  double across_mm;         // its outer size across
};

// Removes the faces within a star-shaped outline around each centre (radius varying 50-100 % with
// nine lobes, on top of the triangles' own staircase): a ragged boundary whose
// perimeter is far longer than pi x its size across. Unreferenced vertices are dropped.
TriMesh with_ragged_holes(const TriMesh& mesh, const std::vector<HoleSpec>& holes) {
  const Eigen::MatrixXd normals = triangle_normals(mesh);
  std::vector<char> removed(static_cast<size_t>(mesh.F.rows()), 0);
  for (const HoleSpec& hole : holes) {
    Eigen::Index centre_vertex = 0;
    (mesh.V.rowwise() - hole.near_mm.transpose()).rowwise().squaredNorm().minCoeff(&centre_vertex);
    const Eigen::Vector3d centre = mesh.V.row(centre_vertex).transpose();
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
      if ((mesh.V.row(mesh.F(f, 0)).transpose() - centre).norm() < 5.0) normal += normals.row(f).transpose();
    normal.normalize();
    const Eigen::Vector3d u = normal.unitOrthogonal(), v = normal.cross(u);
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
      const Eigen::Vector3d d =
          (mesh.V.row(mesh.F(f, 0)) + mesh.V.row(mesh.F(f, 1)) + mesh.V.row(mesh.F(f, 2))).transpose() / 3.0 - centre;
      if (d.norm() > hole.across_mm) continue;  // the other side of the last
      const double angle = std::atan2(d.dot(v), d.dot(u));
      // Whole triangles go: the hole reaches about one edge length beyond the outline, hence the 1.5 mm.
      const double radius = 0.5 * (hole.across_mm - 1.5) * (0.75 + 0.25 * std::sin(9.0 * angle));
      if (std::hypot(d.dot(u), d.dot(v)) < radius) removed[f] = 1;
    }
  }
  // A vertex where the hole's edge touches itself (a pinch) joins two loops: its faces go too, until
  // every hole has one boundary loop.
  for (int round = 0; round < 100; ++round) {
    const MeshTopology topology = build_mesh_topology(mesh.F, mesh.V.rows(), removed);
    if (topology.first_pinch_vertex < 0) break;
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
      for (int k = 0; k < 3; ++k)
        if (mesh.F(f, k) == topology.first_pinch_vertex) removed[f] = 1;
  }
  // Islands of faces left between the lobes belong to the hole: keep the largest kept component only.
  std::vector<char> kept(removed.size());
  for (size_t f = 0; f < kept.size(); ++f) kept[f] = !removed[f];
  int components = 0;
  const std::vector<int> component = face_components(build_mesh_topology(mesh.F, mesh.V.rows()), kept, components);
  const std::vector<double> areas = component_areas(component, components, triangle_areas(mesh));
  const int largest = static_cast<int>(std::max_element(areas.begin(), areas.end()) - areas.begin());
  for (size_t f = 0; f < removed.size(); ++f) removed[f] = component[f] != largest;
  std::vector<int> new_index(static_cast<size_t>(mesh.V.rows()), -1);
  std::vector<Eigen::RowVector3i> faces;
  int used = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    if (removed[f]) continue;
    Eigen::RowVector3i face;
    for (int k = 0; k < 3; ++k) {
      int& index = new_index[mesh.F(f, k)];
      if (index < 0) index = used++;
      face(k) = index;
    }
    faces.push_back(face);
  }
  TriMesh holed;
  holed.V.resize(used, 3);
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    if (new_index[v] >= 0) holed.V.row(new_index[v]) = mesh.V.row(v);
  holed.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f) holed.F.row(static_cast<Eigen::Index>(f)) = faces[f];
  return holed;
}

double loop_length_mm(const TriMesh& mesh, const std::vector<int>& loop) {
  double length = 0.0;
  for (size_t i = 0; i < loop.size(); ++i) length += (mesh.V.row(loop[(i + 1) % loop.size()]) - mesh.V.row(loop[i])).norm();
  return length;
}

class ScanHoles : public ::testing::Test {
 protected:
  void SetUp() override {
    params_ = LastParams::for_eu_size(41, FootSide::Right);  // not mirrored: the implicit shape is the oracle
    params_.target_triangles = 60000;
    last_ = generate_last(params_).mesh;
    length_mm_ = last_.V.col(0).maxCoeff() - last_.V.col(0).minCoeff();
    dir_ = fs::temp_directory_path() / ("lastcut-scan-holes-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Points on the last's sides at mid height, well apart.
  std::vector<HoleSpec> side_holes(const std::vector<double>& across_mm) const {
    std::vector<HoleSpec> holes;
    const double z = 0.5 * (last_.V.col(2).minCoeff() + last_.V.col(2).maxCoeff()) - 10.0;
    for (size_t i = 0; i < across_mm.size(); ++i) {
      const double x = last_.V.col(0).minCoeff() + (0.25 + 0.25 * static_cast<double>(i)) * length_mm_;
      const double y = (i % 2 == 0 ? 1.0 : -1.0) * 200.0;  // beyond the side: the nearest vertex is on it
      holes.push_back({Eigen::Vector3d(x, y, z), across_mm[i]});
    }
    return holes;
  }

  LastParams params_;
  TriMesh last_;
  double length_mm_ = 0;
  fs::path dir_;
};

TEST_F(ScanHoles, RaggedHolesAreMeasuredAcrossAndClosedAlongTheSurface) {
  const LastShape shape(params_);
  for (Eigen::Index v = 0; v < last_.V.rows(); v += 97) ASSERT_LT(std::abs(shape.value(last_.V.row(v))), 0.1);

  TriMesh holed = with_ragged_holes(last_, side_holes({10.0, 20.0, 30.0}));
  const auto loops = build_mesh_topology(holed.F, holed.V.rows()).boundary_loops;
  ASSERT_EQ(loops.size(), 3u);
  for (const auto& loop : loops) {
    const double across = loop_across_mm(holed.V, loop), perimeter = loop_length_mm(holed, loop);
    std::printf("hole: %.1f mm across, %.1f mm around (pi x across = %.1f)\n", across, perimeter,
                std::numbers::pi * across);
    EXPECT_GT(perimeter, 1.2 * std::numbers::pi * across);  // ragged: the old perimeter rule would misjudge it
    EXPECT_LE(across, 30.0);
  }

  // The repair renumbers vertices (the ragged edges' teeth are trimmed first): the patch's vertices
  // are the ones at positions the holed scan did not have.
  std::set<std::array<double, 3>> scanned;
  for (Eigen::Index v = 0; v < holed.V.rows(); ++v) scanned.insert({holed.V(v, 0), holed.V(v, 1), holed.V(v, 2)});
  const std::vector<double> filled = fill_holes(holed, 30.0);
  std::vector<char> is_new(static_cast<size_t>(holed.V.rows()), 0);
  int new_count = 0;
  for (Eigen::Index v = 0; v < holed.V.rows(); ++v)
    if (!scanned.count({holed.V(v, 0), holed.V(v, 1), holed.V(v, 2)})) is_new[v] = 1, ++new_count;
  EXPECT_GT(new_count, 50);
  ASSERT_EQ(filled.size(), 3u);
  EXPECT_TRUE(build_mesh_topology(holed.F, holed.V.rows()).boundary_loops.empty());
  EXPECT_GT(triangle_areas(holed).minCoeff(), 1e-4);
  // The patch follows the last: every new vertex within 0.5 mm of the surface the scan was made from
  // (a flat lid over the 30 mm hole would lie several mm inside the curved side).
  double worst_mm = 0.0;
  for (Eigen::Index v = 0; v < holed.V.rows(); ++v)
    if (is_new[v]) worst_mm = std::max(worst_mm, std::abs(shape.value(holed.V.row(v))));
  std::printf("%d patch vertices, farthest %.3f mm from the last's surface\n", new_count, worst_mm);
  EXPECT_LT(worst_mm, 0.5);
  // Well-shaped and facing outwards: every patch triangle's normal within 30 degrees of the last's
  // surface normal there, and no sliver (smallest angle at least 10 degrees).
  const Eigen::MatrixXd normals = triangle_normals(holed);
  double worst_normal_deg = 0.0, smallest_angle_deg = 180.0;
  for (Eigen::Index f = 0; f < holed.F.rows(); ++f) {
    if (!is_new[holed.F(f, 0)] && !is_new[holed.F(f, 1)] && !is_new[holed.F(f, 2)]) continue;
    const Eigen::Vector3d a = holed.V.row(holed.F(f, 0)), b = holed.V.row(holed.F(f, 1)), c = holed.V.row(holed.F(f, 2));
    const Eigen::Vector3d surface_normal = shape.gradient((a + b + c) / 3.0).normalized();
    worst_normal_deg = std::max(worst_normal_deg, std::acos(std::clamp(normals.row(f).dot(surface_normal), -1.0, 1.0)) * 180.0 / std::numbers::pi);
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d p = holed.V.row(holed.F(f, k)), q = holed.V.row(holed.F(f, (k + 1) % 3)),
                            r = holed.V.row(holed.F(f, (k + 2) % 3));
      smallest_angle_deg = std::min(smallest_angle_deg, std::acos(std::clamp((q - p).normalized().dot((r - p).normalized()), -1.0, 1.0)) * 180.0 / std::numbers::pi);
    }
  }
  std::printf("patch triangles: normals within %.1f deg of the surface's, smallest angle %.1f deg\n", worst_normal_deg,
              smallest_angle_deg);
  EXPECT_LT(worst_normal_deg, 30.0);
  EXPECT_GT(smallest_angle_deg, 10.0);
}

TEST_F(ScanHoles, HolesOfTenTwentyAndThirtyMillimetresGiveMoldsWithTheRepairReported) {
  const fs::path scan = dir_ / "holed.stl";
  write_stl_binary(scan, with_ragged_holes(last_, side_holes({10.0, 20.0, 30.0})));
  const ScanResult result = scan_to_molds(scan, {});
  ASSERT_EQ(result.segments.size(), 2u);
  for (const std::string& note : result.notes) std::printf("note: %s\n", note.c_str());
  for (const SegmentResult& segment : result.segments) {
    std::printf("%s: D_angle %.4f D_area %.4f, %d triangles\n", segment.name.c_str(), segment.measures.D_angle,
                segment.measures.D_area, segment.mesh3d.triangle_count());
    EXPECT_EQ(segment.measures.flipped_triangles, 0) << segment.name;
    EXPECT_LT(segment.measures.D_angle, 2.05) << segment.name;
  }
  bool reported = false;
  for (const std::string& note : result.notes) {
    if (note.rfind("closed 3 scan holes (", 0) == 0 && note.find("mm across) with a smooth patch") != std::string::npos)
      reported = true;
  }
  EXPECT_TRUE(reported) << ::testing::PrintToString(result.notes);
}

TEST_F(ScanHoles, AFortyMillimetreHoleIsRefusedWithOneClearLine) {
  const fs::path scan = dir_ / "big-hole.stl";
  write_stl_binary(scan, with_ragged_holes(last_, side_holes({40.0})));
  try {
    scan_to_molds(scan, {});
    FAIL() << "a 40 mm hole was closed";
  } catch (const EngineError& error) {
    const std::string what = error.what();
    EXPECT_EQ(what.find('\n'), std::string::npos);
    EXPECT_EQ(what.rfind("not a closed last: 1 boundary loop up to ", 0), 0u) << what;
    EXPECT_NE(what.find(" mm across, larger than the 30 mm scan holes are closed up to; use --no-segment"),
              std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace lastcut
