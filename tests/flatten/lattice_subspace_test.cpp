// The lattice subspace of ARAP's global step (lattice_subspace.hpp): trilinear functions reproduce linear
// ones exactly, so the Galerkin correction of a residual made by a linear map returns that map, and the
// correction of any residual leaves a remainder orthogonal to every linear map (Galerkin orthogonality).
// Two-level flattening reaches the exact development of a developable patch and, on a doubly curved cap,
// the same map as the plain full-step iteration run to convergence.
#include <gtest/gtest.h>

#include <random>

#include "engine/core/engine_error.hpp"
#include "engine/flatten/cotangent_laplacian.hpp"
#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/flatten.hpp"
#include "engine/flatten/lattice_subspace.hpp"
#include "tests/flatten/flatten_fixtures.hpp"

namespace lastcut {
namespace {

struct System {
  TriMesh mesh;
  ReducedLaplacian laplacian;
};

System system_of(const TriMesh& mesh) {
  const MeshTopology topology = check_disk(mesh);
  const TriangleFrames frames = compute_triangle_frames(mesh);
  return {mesh, pinned_cotangent_laplacian(frames, topology)};
}

// A linear map of the 3D positions to 2D, at the reduced system's rows (mm).
Eigen::MatrixXd linear_map(const System& s, const Eigen::Matrix<double, 3, 2>& A, const Eigen::RowVector2d& b) {
  Eigen::MatrixXd w(s.laplacian.matrix.rows(), 2);
  for (Eigen::Index r = 0; r < w.rows(); ++r) w.row(r) = s.mesh.V.row(s.laplacian.vertex_of_row[r]) * A + b;
  return w;
}

TEST(LatticeSubspace, ReturnsALinearMapFromItsResidual) {
  const System s = system_of(testing::spherical_cap(60.0, 70.0, 30, 60));
  Eigen::Matrix<double, 3, 2> A;
  A << 0.8, -0.3, 0.25, 1.1, -0.6, 0.4;
  const Eigen::MatrixXd w = linear_map(s, A, Eigen::RowVector2d(12.0, -7.0));
  for (const double cell_mm : {4.0, 9.0, 25.0}) {
    const LatticeSubspace subspace(s.mesh, s.laplacian, cell_mm);
    const Eigen::MatrixXd x = subspace.correction(s.laplacian.matrix * w);
    EXPECT_LE((x - w).cwiseAbs().maxCoeff(), 1e-6 * w.cwiseAbs().maxCoeff()) << "cell " << cell_mm << " mm";
    EXPECT_GT(subspace.node_count(), 8);
  }
}

TEST(LatticeSubspace, RemainderIsOrthogonalToLinearMaps) {
  const System s = system_of(testing::cone_patch(30.0, 100.0, 40.0, 120.0, 30, 15).mesh);
  const LatticeSubspace subspace(s.mesh, s.laplacian, 10.0);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd residual(s.laplacian.matrix.rows(), 2);
  for (Eigen::Index i = 0; i < residual.size(); ++i) residual.data()[i] = uniform(random);
  const Eigen::MatrixXd remainder = residual - s.laplacian.matrix * subspace.correction(residual);
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::Matrix<double, 3, 2> A = Eigen::Matrix<double, 3, 2>::Zero();
    A(axis, 0) = 1.0;
    const Eigen::MatrixXd w = linear_map(s, A, Eigen::RowVector2d(3.0, 0.0));
    const double scale = w.col(0).norm() * residual.col(0).norm();
    EXPECT_LE(std::abs(w.col(0).dot(remainder.col(0))), 1e-9 * scale) << "axis " << axis;
  }
}

TEST(LatticeSubspace, RefusesANonPositiveCell) {
  const System s = system_of(testing::spherical_cap(60.0, 70.0, 10, 20));
  EXPECT_THROW(LatticeSubspace(s.mesh, s.laplacian, 0.0), EngineError);
}

TEST(LatticeSubspace, TwoLevelFlatteningGivesTheDevelopmentOfAConePatch) {
  // The plane-rotation start is near, not at, a cone's development (plane_start_test.cpp).
  const testing::DevelopablePatch patch = testing::cone_patch(30.0, 100.0, 40.0, 120.0, 40, 20);
  const FlattenResult r = flatten(patch.mesh);
  EXPECT_GT(r.subspace_iterations, 0);
  EXPECT_LE(testing::max_distance_after_rigid_alignment(r.UV, patch.development), 1e-3);
  std::printf("cone: %d subspace + %d full iterations\n", r.subspace_iterations, r.iterations);
}

TEST(LatticeSubspace, TwoLevelFlatteningReachesTheConvergedMapOfACap) {
  // A spherical cap is not developable: the converged ARAP map is known only numerically, so the plain
  // full-step iteration run to 1e-13 is the reference.
  const TriMesh cap = testing::spherical_cap(60.0, 80.0, 40, 80);
  FlattenOptions plain;
  plain.lattice_cells = 0;
  plain.relative_energy_tolerance = 1e-13;
  plain.max_iterations = 5000;
  const FlattenResult reference = flatten(cap, plain);
  ASSERT_TRUE(reference.converged);
  const FlattenResult two_level = flatten(cap);
  EXPECT_GT(two_level.subspace_iterations, 0);
  EXPECT_EQ(two_level.flipped_triangles, 0);
  EXPECT_LE(testing::max_distance_after_rigid_alignment(two_level.UV, reference.UV), 0.05);
  std::printf("cap: two-level %d subspace + %d full iterations, plain %d\n", two_level.subspace_iterations,
              two_level.iterations, reference.iterations);
}

}  // namespace
}  // namespace lastcut
