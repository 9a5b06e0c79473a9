#pragma once
// Distortion of a flattening, as the thesis measures it (M. Sabaliauskas, doctoral thesis summary,
// Vilnius University 2017, section 2.3): per triangle, sigma1 >= sigma2 are the singular values of the
// 2x2 Jacobian of the map from the triangle's isometric 2D frame to UV (thesis Algorithm 1, svd2x2), and
//   D_angle = sum_j S_j (sigma1/sigma2 + sigma2/sigma1) / sum_i S_i               (eq. 1)
//   D_area  = sum_j S_j (sigma1 sigma2 + 1/(sigma1 sigma2))^Theta / sum_i S_i, Theta = 1   (eq. 2)
// with S the 3D triangle areas. Both are 2 for an isometry (the ideal) and grow with distortion.
#include <Eigen/Core>

#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"

namespace lastcut {

struct DistortionMeasures {
  double D_angle = 0, D_area = 0;                   // eq. (1), eq. (2) with Theta = 1; 2 is ideal
  double area_3d_mm2 = 0, area_2d_mm2 = 0, area_error_pct = 0;  // 2D area is signed (flips count negative)
  double boundary_3d_mm = 0, boundary_2d_mm = 0, boundary_error_pct = 0;
  int flipped_triangles = 0;                        // UV triangles with signed area <= 0
  double max_stretch = 0, p95_stretch = 0;          // largest and 95th-percentile sigma1
  Eigen::VectorXd sigma1, sigma2;                   // #F, per triangle singular values
};

// mesh3d: the 3D disk (mm); UV: #V x 2 (mm), same vertex order. Throws EngineError on mismatched sizes.
// A triangle collapsed to zero area in UV makes D_angle and D_area infinite, as the formulas say.
DistortionMeasures measure_distortion(const TriMesh& mesh3d, const Eigen::MatrixXd& UV);
// The same with the disk's topology already checked (check_disk in disk_topology.hpp).
DistortionMeasures measure_distortion(const TriMesh& mesh3d, const Eigen::MatrixXd& UV, const MeshTopology& topology);

// Number of triangles whose UV image has signed area <= 0 (flipped or collapsed).
int count_flipped_triangles(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV);

}  // namespace lastcut
