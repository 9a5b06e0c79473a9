// The boundary-first start map (Sawhney & Crane 2017 with u = 0 on the boundary): on a developable
// patch it IS the development (zero angle defects give u = 0, the boundary polygon closes by itself and
// the development's coordinates are discrete-harmonic, since cotangent weights are intrinsic and
// reproduce linear functions); on a sphere cap it shrinks the interior (u < 0) and keeps the boundary's
// length; on the FIND foot reference half ARAP from it needs fewer iterations than from the plane start.
#include "engine/flatten/boundary_first_start.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include "engine/flatten/flatten.hpp"
#include "tests/flatten/flatten_fixtures.hpp"

namespace lastcut {
namespace {

Eigen::MatrixXd start_of(const TriMesh& mesh) {
  const MeshTopology topology = check_disk(mesh);
  const TriangleFrames frames = compute_triangle_frames(mesh);
  ReducedLaplacian laplacian = pinned_cotangent_laplacian(frames, topology);
  SparseCholesky factor;
  factor.analyze_pattern(laplacian.matrix);
  return boundary_first_start(mesh, frames, topology, laplacian, factor);
}

TEST(BoundaryFirstStart, IsTheDevelopmentOfACylinderAndAConePatch) {
  for (const testing::DevelopablePatch& patch : {testing::cylinder_patch(50.0, 150.0, 80.0, 40, 20),
                                                 testing::cone_patch(30.0, 100.0, 40.0, 120.0, 40, 20)}) {
    const Eigen::MatrixXd start = start_of(patch.mesh);
    EXPECT_EQ(count_flipped_triangles(patch.mesh.F, start), 0);
    EXPECT_LE(testing::max_distance_after_rigid_alignment(start, patch.development), 1e-6);
  }
}

TEST(BoundaryFirstStart, OnASphereCapKeepsTheBoundaryLengthAndIsConformal) {
  const TriMesh cap = testing::spherical_cap(60.0, 60.0, 20, 60);
  const Eigen::MatrixXd start = start_of(cap);
  const DistortionMeasures d = measure_distortion(cap, start);
  EXPECT_EQ(d.flipped_triangles, 0);
  // The boundary keeps its length up to the closing step's change (none here: the cap is symmetric).
  EXPECT_NEAR(d.boundary_error_pct, 0.0, 0.01);
  // Conformal up to the discretisation: the angle term stays near its ideal 2 while the area must
  // shrink (a flat disk with the cap's rim holds less area than the cap).
  EXPECT_LT(d.D_angle, 2.002);
  EXPECT_LT(d.area_error_pct, -5.0);
}

TEST(BoundaryFirstStart, ArapFromItConvergesFasterOnTheFindReferenceHalf) {
  const TriMesh half =
      testing::read_off(std::string(LASTCUT_SHARED_DATA_DIR) + "/meshes/find-template-half-52k.off", 1000.0);
  FlattenOptions plane;
  plane.start = ArapStart::PlaneRotation;
  const FlattenResult from_plane = flatten(half, plane);
  FlattenOptions boundary_first;
  boundary_first.start = ArapStart::BoundaryFirst;
  const FlattenResult from_boundary = flatten(half, boundary_first);
  std::printf("iterations: %d from the boundary-first start, %d from the plane start; energy %.2f vs %.2f mm^2\n",
              from_boundary.iterations, from_plane.iterations, from_boundary.energy_final, from_plane.energy_final);
  EXPECT_LT(from_boundary.iterations, from_plane.iterations);
  EXPECT_LE(from_boundary.energy_final, from_plane.energy_final * 1.001);
  EXPECT_EQ(from_boundary.flipped_triangles, 0);
}

}  // namespace
}  // namespace lastcut
