// The simulated scan: the same seed gives the same scan, noise has the asked sigma along the
// normals, holes are the asked number of small loops away from the top cut, and the random pose
// is a rigid motion recorded in canonical_to_scan. Also: the binary STL writer's exact size.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "engine/lastgen/generate_last.hpp"
#include "engine/lastgen/last_shape.hpp"
#include "mesh_checks.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

LastParams scan_params() {
  LastParams params;
  params.side = FootSide::Left;
  params.target_triangles = 5000;
  return params;
}

TEST(SimulatedScan, SameSeedSameScanOtherSeedOtherScan) {
  LastParams params = scan_params();
  params.noise_mm = 0.2;
  params.holes = 2;
  params.random_pose = true;
  params.seed = 7;
  const GeneratedLast a = generate_last(params), b = generate_last(params);
  EXPECT_TRUE(a.mesh.V == b.mesh.V);
  EXPECT_TRUE(a.mesh.F == b.mesh.F);
  EXPECT_TRUE(a.canonical_to_scan.matrix() == b.canonical_to_scan.matrix());
  params.seed = 8;
  const GeneratedLast c = generate_last(params);
  EXPECT_FALSE(c.canonical_to_scan.matrix().isApprox(a.canonical_to_scan.matrix(), 1e-3));
}

TEST(SimulatedScan, NoiseHasTheRequestedSigmaAlongTheNormals) {
  LastParams params = scan_params();
  const TriMesh clean = generate_last(params).mesh;
  params.noise_mm = 0.3;
  const TriMesh noisy = generate_last(params).mesh;
  ASSERT_EQ(clean.V.rows(), noisy.V.rows());
  const Eigen::VectorXd displacement = (noisy.V - clean.V).rowwise().norm();
  const double rms = std::sqrt(displacement.squaredNorm() / static_cast<double>(displacement.size()));
  EXPECT_NEAR(rms, 0.3, 0.03);
  EXPECT_TRUE(noisy.F == clean.F);
  EXPECT_EQ(test::edge_census(noisy).boundary_edges, 0);
}

TEST(SimulatedScan, HolesAreSmallSeparateLoopsAwayFromTheTopCut) {
  LastParams params = scan_params();
  params.target_triangles = 12000;  // ~2.7 mm edges: one-ring holes ~5 mm across
  params.holes = 4;
  const TriMesh mesh = generate_last(params).mesh;
  const test::EdgeCensus census = test::edge_census(mesh);
  EXPECT_EQ(census.boundary_loops, 4);
  EXPECT_EQ(census.non_manifold_edges, 0);
  EXPECT_EQ(census.inconsistent_edges, 0);
  EXPECT_LT(mesh.triangle_count(), params.target_triangles);
  EXPECT_GT(mesh.triangle_count(), params.target_triangles - 4 * 40);
  // Each hole is a few mm across, below the top cut, and the holes are apart.
  const LastShape shape(params);
  std::vector<Eigen::Vector3d> centres;
  for (const std::vector<int>& loop : census.loop_vertices) {
    Eigen::Vector3d low = Eigen::Vector3d::Constant(1e9), high = -low, sum = Eigen::Vector3d::Zero();
    for (const int v : loop) {
      const Eigen::Vector3d p = mesh.V.row(v);
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
      sum += p;
      EXPECT_LT(p.z(), shape.top_cut_z_mm(p.x()) - 3.0) << "hole on the top cut";
    }
    EXPECT_GT((high - low).norm(), 2.0);
    EXPECT_LT((high - low).norm(), 12.0);
    centres.push_back(sum / static_cast<double>(loop.size()));
  }
  for (size_t i = 0; i < centres.size(); ++i)
    for (size_t j = i + 1; j < centres.size(); ++j) EXPECT_GT((centres[i] - centres[j]).norm(), 20.0);
}

TEST(SimulatedScan, RandomPoseIsTheRecordedRigidMotion) {
  LastParams params = scan_params();
  const TriMesh canonical = generate_last(params).mesh;
  params.random_pose = true;
  const GeneratedLast posed = generate_last(params);
  const Eigen::Matrix3d R = posed.canonical_to_scan.linear();
  EXPECT_TRUE((R.transpose() * R).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
  EXPECT_FALSE(posed.canonical_to_scan.isApprox(Eigen::Affine3d::Identity(), 1e-3));
  TriMesh back = posed.mesh;
  const Eigen::Affine3d inverse = posed.canonical_to_scan.inverse();
  for (Eigen::Index v = 0; v < back.V.rows(); ++v)
    back.V.row(v) = (inverse * Eigen::Vector3d(back.V.row(v).transpose())).transpose();
  EXPECT_LT((back.V - canonical.V).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_NEAR(test::signed_volume_mm3(posed.mesh), test::signed_volume_mm3(canonical), 1e-3);
}

TEST(SimulatedScan, BinaryStlHasExactlyTheStandardSize) {
  LastParams params = scan_params();
  const TriMesh mesh = generate_last(params).mesh;
  const test::TempDir folder("lastgen-scan");
  const std::filesystem::path path = folder / "last.stl";
  write_stl_binary(path, mesh);
  EXPECT_EQ(std::filesystem::file_size(path), 84u + 50u * static_cast<unsigned>(mesh.triangle_count()));
  std::ifstream in(path, std::ios::binary);
  char header[84];
  in.read(header, 84);
  uint32_t count = 0;
  std::memcpy(&count, header + 80, 4);
  EXPECT_EQ(count, static_cast<uint32_t>(mesh.triangle_count()));
}

}  // namespace
}  // namespace lastcut
