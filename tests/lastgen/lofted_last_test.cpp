// The scanner-like meshes of `lastcut generate`: a lofted last is one closed, outward, manifold
// sphere of about the asked triangle count, lying on the same solid as the remeshed last (its
// vertices on the surface, its volume within 1 %), with slivers at the poles; isotropic noise has
// the asked sigma per axis, and unlike normal noise it also moves vertices along the surface.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/lastgen/generate_last.hpp"
#include "engine/lastgen/last_shape.hpp"
#include "mesh_checks.hpp"

namespace lastcut {
namespace {

LastParams lofted_params() {
  LastParams params = LastParams::for_eu_size(41, FootSide::Right);
  params.surface = LastSurface::Lofted;
  params.target_triangles = 20000;
  return params;
}

TEST(LoftedLast, IsAClosedOutwardSphereOnTheSolidWithSliversAtThePoles) {
  const LastParams params = lofted_params();
  const TriMesh lofted = generate_last(params).mesh;
  EXPECT_NEAR(lofted.triangle_count(), 20000, 400);
  const test::EdgeCensus census = test::edge_census(lofted);
  EXPECT_EQ(census.boundary_edges, 0);
  EXPECT_EQ(census.non_manifold_edges, 0);
  EXPECT_EQ(census.inconsistent_edges, 0);
  EXPECT_EQ(test::euler_characteristic(lofted), 2);
  LastParams remeshed_params = params;
  remeshed_params.surface = LastSurface::Remeshed;
  const double remeshed_volume = test::signed_volume_mm3(generate_last(remeshed_params).mesh);
  EXPECT_NEAR(test::signed_volume_mm3(lofted) / remeshed_volume, 1.0, 0.01);
  LastParams canonical = params;
  canonical.side = FootSide::Right;  // right lasts are not mirrored: vertices are in the shape's frame
  const LastShape shape(canonical);
  double worst_mm = 0;
  for (Eigen::Index v = 0; v < lofted.V.rows(); ++v)
    worst_mm = std::max(worst_mm, std::abs(shape.value(lofted.V.row(v).transpose())));
  EXPECT_LT(worst_mm, 0.05);
  EXPECT_LT(test::worst_triangle_quality(lofted), 0.05) << "the pole fans are slivers";
}

TEST(LoftedLast, IsotropicNoiseHasTheSigmaPerAxisAndMovesAlongTheSurfaceToo) {
  LastParams params = lofted_params();
  const TriMesh clean = generate_last(params).mesh;
  params.noise_mm = 0.2;
  params.noise_kind = ScanNoise::Isotropic;
  const TriMesh noisy = generate_last(params).mesh;
  ASSERT_EQ(clean.V.rows(), noisy.V.rows());
  const Eigen::MatrixXd moved = noisy.V - clean.V;
  for (int axis = 0; axis < 3; ++axis)
    EXPECT_NEAR(std::sqrt(moved.col(axis).squaredNorm() / static_cast<double>(moved.rows())), 0.2, 0.01);
  params.noise_kind = ScanNoise::AlongNormal;
  const Eigen::MatrixXd along_normals = generate_last(params).mesh.V - clean.V;
  // 3D displacement: sqrt(3) sigma for isotropic noise, sigma for normal noise.
  const auto rms = [](const Eigen::MatrixXd& d) { return std::sqrt(d.squaredNorm() / static_cast<double>(d.rows())); };
  EXPECT_NEAR(rms(moved), 0.2 * std::sqrt(3.0), 0.02);
  EXPECT_NEAR(rms(along_normals), 0.2, 0.02);
}

}  // namespace
}  // namespace lastcut
