// Distortion measures of a flattening (thesis eq. 1 and 2); see distortion.hpp.
#include "engine/flatten/distortion.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/svd2x2.hpp"

namespace lastcut {

int count_flipped_triangles(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV) {
  int count = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector2d a = UV.row(F(f, 1)) - UV.row(F(f, 0));
    const Eigen::Vector2d b = UV.row(F(f, 2)) - UV.row(F(f, 0));
    count += (a.x() * b.y() - a.y() * b.x()) <= 0.0 ? 1 : 0;
  }
  return count;
}

DistortionMeasures measure_distortion(const TriMesh& mesh, const Eigen::MatrixXd& UV) {
  return measure_distortion(mesh, UV, check_disk(mesh));
}

DistortionMeasures measure_distortion(const TriMesh& mesh, const Eigen::MatrixXd& UV, const MeshTopology& topology) {
  if (UV.rows() != mesh.V.rows() || UV.cols() != 2) {
    throw EngineError("flattening has " + std::to_string(UV.rows()) + " points for a mesh of " +
                      std::to_string(mesh.V.rows()) + " vertices");
  }
  const int face_count = mesh.triangle_count();
  DistortionMeasures m;
  m.sigma1.resize(face_count);
  m.sigma2.resize(face_count);
  double angle_sum = 0.0, area_sum = 0.0;
  for (int f = 0; f < face_count; ++f) {
    const Eigen::Vector3d p0 = mesh.V.row(mesh.F(f, 0)), p1 = mesh.V.row(mesh.F(f, 1)), p2 = mesh.V.row(mesh.F(f, 2));
    const Eigen::Vector3d e1 = p1 - p0, e2 = p2 - p0;
    const double twice_area = e1.cross(e2).norm();
    const double l1 = e1.norm();
    Eigen::Matrix2d X;  // the triangle's edges in its isometric 2D frame (columns)
    X << l1, e2.dot(e1) / l1, 0.0, twice_area / l1;
    Eigen::Matrix2d Y;  // the same edges in UV
    Y.col(0) = (UV.row(mesh.F(f, 1)) - UV.row(mesh.F(f, 0))).transpose();
    Y.col(1) = (UV.row(mesh.F(f, 2)) - UV.row(mesh.F(f, 0))).transpose();
    const double area3 = 0.5 * twice_area;
    const double signed_area2 = 0.5 * (Y(0, 0) * Y(1, 1) - Y(1, 0) * Y(0, 1));
    m.area_3d_mm2 += area3;
    m.area_2d_mm2 += signed_area2;
    m.flipped_triangles += signed_area2 <= 0.0 ? 1 : 0;
    if (!(twice_area > 0.0)) {  // a zero-area 3D triangle weighs nothing in eq. (1) and (2)
      m.sigma1(f) = m.sigma2(f) = 0.0;
      continue;
    }
    const Svd2 svd = svd2x2(Y * X.inverse());
    const double s1 = svd.sigma(0), s2 = svd.sigma(1);
    m.sigma1(f) = s1;
    m.sigma2(f) = s2;
    const double inf = std::numeric_limits<double>::infinity();
    angle_sum += area3 * (s2 > 0.0 ? s1 / s2 + s2 / s1 : inf);
    area_sum += area3 * (s2 > 0.0 ? s1 * s2 + 1.0 / (s1 * s2) : inf);
  }
  m.D_angle = angle_sum / m.area_3d_mm2;
  m.D_area = area_sum / m.area_3d_mm2;
  m.area_error_pct = 100.0 * (m.area_2d_mm2 - m.area_3d_mm2) / m.area_3d_mm2;

  if (topology.boundary_loops.size() != 1) throw EngineError("distortion is measured on a disk with one boundary loop");
  const auto& loop = topology.boundary_loops[0];
  for (size_t i = 0; i < loop.size(); ++i) {
    const int a = loop[i], b = loop[(i + 1) % loop.size()];
    m.boundary_3d_mm += (mesh.V.row(b) - mesh.V.row(a)).norm();
    m.boundary_2d_mm += (UV.row(b) - UV.row(a)).norm();
  }
  m.boundary_error_pct = 100.0 * (m.boundary_2d_mm - m.boundary_3d_mm) / m.boundary_3d_mm;

  if (face_count > 0) {
    m.max_stretch = m.sigma1.maxCoeff();
    std::vector<double> sorted(m.sigma1.data(), m.sigma1.data() + face_count);
    const size_t k = std::min(sorted.size() - 1, static_cast<size_t>(std::ceil(0.95 * sorted.size())) - 1);
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k), sorted.end());
    m.p95_stretch = sorted[k];
  }
  return m;
}

}  // namespace lastcut
