// ABF++ on small meshes with known answers: a planar disk keeps its own angles (also from a perturbed
// Newton start) and is rebuilt exactly; on a doubly curved cap the angle constraints hold after the solve,
// checked here by an independent computation, and the rebuilt map has those angles; bad input and a
// Newton stopped early are reported in one line.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "engine/core/engine_error.hpp"
#include "engine/flatten/abf_angles.hpp"
#include "engine/flatten/abf_reconstruction.hpp"
#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/flatten.hpp"
#include "tests/flatten/flatten_fixtures.hpp"

namespace lastcut {
namespace {

constexpr double kPi = std::numbers::pi;

// A flat, irregular disk (z = 0): the warped grid of a cylinder's development with its interior jiggled.
TriMesh planar_disk() {
  const testing::DevelopablePatch patch = testing::cylinder_patch(40.0, 120.0, 60.0, 10, 8);
  TriMesh disk;
  disk.F = patch.mesh.F;
  disk.V = Eigen::MatrixXd::Zero(patch.development.rows(), 3);
  disk.V.leftCols(2) = patch.development;
  for (int j = 1; j < 8; ++j)
    for (int i = 1; i < 10; ++i) {
      const int v = j * 11 + i;
      disk.V(v, 0) += 1.5 * std::sin(3.1 * v);
      disk.V(v, 1) += 1.5 * std::cos(2.3 * v);
    }
  return disk;
}

// Corner angles of a 2D or 3D triangle mesh (3 #F, rad), by acos of normalized dot products.
std::vector<double> corner_angles(const Eigen::MatrixXd& P, const Eigen::MatrixXi& F) {
  std::vector<double> angles;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Eigen::VectorXd a = (P.row(F(f, (k + 1) % 3)) - P.row(F(f, k))).normalized();
      const Eigen::VectorXd b = (P.row(F(f, (k + 2) % 3)) - P.row(F(f, k))).normalized();
      angles.push_back(std::acos(a.dot(b)));
    }
  return angles;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst;
}

TEST(AbfAngles, PlanarDiskKeepsItsOwnAnglesAndIsRebuiltExactly) {
  const TriMesh disk = planar_disk();
  const MeshTopology topology = check_disk(disk);
  const std::vector<double> own = corner_angles(disk.V, disk.F);
  // A flat disk's angles already meet every constraint: no Newton step, nothing changed.
  const AbfAngles solved = solve_abf_angles(disk, topology);
  EXPECT_TRUE(solved.converged);
  EXPECT_EQ(solved.iterations, 0);
  EXPECT_LT(max_difference(solved.alpha, own), 1e-12);

  // From a start 5 % off, Newton must come back to the same angles.
  std::vector<double> start = own;
  for (size_t c = 0; c < start.size(); ++c) start[c] *= 1.0 + 0.05 * std::sin(1.7 * static_cast<double>(c));
  const AbfAngles back = solve_abf_angles(disk.F, topology, own, start);
  EXPECT_TRUE(back.converged);
  EXPECT_GT(back.iterations, 0);
  EXPECT_LE(back.iterations, 10);
  EXPECT_LE(back.gradient_norm, 1e-6);
  EXPECT_LT(max_difference(back.alpha, own), 1e-8);

  // The angles rebuild the disk itself, up to a rigid motion (the area is the disk's own).
  const Eigen::MatrixXd UV = reconstruct_from_angles(disk, topology, back.alpha);
  EXPECT_LT(testing::max_distance_after_rigid_alignment(UV, disk.V.leftCols(2)), 1e-6);
}

TEST(AbfAngles, ConstraintsHoldOnADoublyCurvedCap) {
  const TriMesh cap = testing::spherical_cap(50.0, 60.0, 12, 24);
  const MeshTopology topology = check_disk(cap);
  const AbfAngles solved = solve_abf_angles(cap, topology);
  ASSERT_TRUE(solved.converged);
  EXPECT_GT(solved.iterations, 0);
  EXPECT_LE(solved.gradient_norm, 1e-6);

  // Independently of the solver: triangle sums, interior vertex sums and the law-of-sines wheel product.
  const std::vector<char> interior = interior_vertices(topology);
  std::vector<double> vertex_sum(cap.V.rows(), 0.0), wheel_product(cap.V.rows(), 1.0);
  double worst_triangle = 0.0;
  for (Eigen::Index f = 0; f < cap.F.rows(); ++f) {
    const double* a = &solved.alpha[3 * f];
    worst_triangle = std::max(worst_triangle, std::abs(a[0] + a[1] + a[2] - kPi));
    for (int k = 0; k < 3; ++k) {
      vertex_sum[cap.F(f, k)] += a[k];
      // At vertex F(f,k): |edge to F(f,k+2)| / |edge to F(f,k+1)| = sin a[k+1] / sin a[k+2]; closes around v.
      wheel_product[cap.F(f, k)] *= std::sin(a[(k + 1) % 3]) / std::sin(a[(k + 2) % 3]);
    }
  }
  double worst_vertex = 0.0, worst_wheel = 0.0;
  int interior_count = 0;
  for (Eigen::Index v = 0; v < cap.V.rows(); ++v) {
    if (!interior[v]) continue;
    ++interior_count;
    worst_vertex = std::max(worst_vertex, std::abs(vertex_sum[v] - 2.0 * kPi));
    worst_wheel = std::max(worst_wheel, std::abs(wheel_product[v] - 1.0));
  }
  EXPECT_EQ(interior_count, 1 + 11 * 24);
  EXPECT_LT(worst_triangle, 1e-6);
  EXPECT_LT(worst_vertex, 1e-6);
  EXPECT_LT(worst_wheel, 1e-6);
  const AbfResiduals residuals = abf_residuals(cap.F, topology, solved.alpha);
  EXPECT_NEAR(residuals.triangle_rad, worst_triangle, 1e-12);
  EXPECT_NEAR(residuals.vertex_rad, worst_vertex, 1e-12);
  // The 3D angles themselves do not close: the cap is curved (the test would pass trivially otherwise).
  const AbfResiduals curved = abf_residuals(cap.F, topology, corner_angles(cap.V, cap.F));
  EXPECT_GT(curved.vertex_rad, 1e-3);

  // Consistent angles: the rebuilt map has exactly these angles, and the 3D area.
  const Eigen::MatrixXd UV = reconstruct_from_angles(cap, topology, solved.alpha);
  EXPECT_LT(max_difference(corner_angles(UV, cap.F), solved.alpha), 1e-6);
  const DistortionMeasures d = measure_distortion(cap, UV);
  EXPECT_EQ(d.flipped_triangles, 0);
  EXPECT_NEAR(d.area_error_pct, 0.0, 1e-9);

  // Through flatten(): ABF++ keeps angles (near LSCM's D_angle, printed) better than ARAP does.
  FlattenOptions options;
  options.method = FlattenMethod::Abf;
  const DistortionMeasures abf = measure_distortion(cap, flatten(cap, options).UV);
  options.method = FlattenMethod::Lscm;
  const DistortionMeasures lscm = measure_distortion(cap, flatten(cap, options).UV);
  options.method = FlattenMethod::Arap;
  const DistortionMeasures arap = measure_distortion(cap, flatten(cap, options).UV);
  EXPECT_LT(abf.D_angle, arap.D_angle);
  EXPECT_LT(abf.D_angle, 2.01);
  std::printf("cap D_angle / D_area: ABF++ %.5f / %.5f, LSCM %.5f / %.5f, ARAP %.5f / %.5f\n", abf.D_angle,
              abf.D_area, lscm.D_angle, lscm.D_area, arap.D_angle, arap.D_area);
}

TEST(AbfFlatten, StoppedNewtonKeepsItsBestAnglesWithOneNote) {
  const TriMesh cap = testing::spherical_cap(50.0, 60.0, 12, 24);
  FlattenOptions options;
  options.method = FlattenMethod::Abf;
  options.abf_max_newton_iterations = 1;
  const FlattenResult stopped = flatten(cap, options);
  EXPECT_FALSE(stopped.converged);
  EXPECT_EQ(stopped.iterations, 1);
  EXPECT_EQ(stopped.factorizations, 2);  // one Newton step, one reconstruction
  EXPECT_EQ(stopped.flipped_triangles, 0);
  ASSERT_EQ(stopped.notes.size(), 1u);
  EXPECT_NE(stopped.notes[0].find("ABF++ Newton stopped after 1 iterations"), std::string::npos) << stopped.notes[0];
  EXPECT_EQ(stopped.notes[0].find('\n'), std::string::npos);

  options.abf_max_newton_iterations = 50;
  const FlattenResult full = flatten(cap, options);
  EXPECT_TRUE(full.converged);
  EXPECT_TRUE(full.notes.empty());
  EXPECT_GT(full.iterations, 1);
  EXPECT_EQ(full.factorizations, full.iterations + 1);
}

TEST(AbfFlatten, RefusesWhatIsNotADiskAsArapDoes) {
  const TriMesh ring = testing::cylinder_patch(30.0, 360.0, 40.0, 12, 3).mesh;
  TriMesh tube;  // the ring with its seam welded: two boundary loops
  tube.V.resize(12 * 4, 3);
  for (int v = 0; v < 13 * 4; ++v)
    if (v % 13 != 12) tube.V.row(v / 13 * 12 + v % 13) = ring.V.row(v);
  tube.F = ring.F.unaryExpr([](int v) { return v / 13 * 12 + v % 13 % 12; });
  FlattenOptions abf, arap;
  abf.method = FlattenMethod::Abf;
  std::string abf_error, arap_error;
  try {
    flatten(tube, abf);
  } catch (const EngineError& e) {
    abf_error = e.what();
  }
  try {
    flatten(tube, arap);
  } catch (const EngineError& e) {
    arap_error = e.what();
  }
  EXPECT_NE(abf_error.find("more than one boundary loop"), std::string::npos) << abf_error;
  EXPECT_EQ(abf_error, arap_error);

  abf.abf_max_newton_iterations = -1;
  EXPECT_THROW(flatten(ring, abf), EngineError);
  const std::vector<double> wrong_size(5, 1.0);
  EXPECT_THROW(solve_abf_angles(ring.F, check_disk(ring), wrong_size, wrong_size), EngineError);
}

}  // namespace
}  // namespace lastcut
