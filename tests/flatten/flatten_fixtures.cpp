// Developable test patches, OFF reading, subdivision and rigid alignment; see flatten_fixtures.hpp.
#include "tests/flatten/flatten_fixtures.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <string>
#include <utility>

#include "engine/core/engine_error.hpp"

namespace lastcut::testing {
namespace {

// Non-uniform spacing in [0, 1]: a smooth warp, so neighbouring rows differ in width.
double warped(int i, int count) {
  const double t = static_cast<double>(i) / count;
  return t + 0.04 * std::sin(2.0 * std::numbers::pi * t) + 0.01 * std::sin(14.0 * std::numbers::pi * t);
}

// Quads (i, j) .. (i+1, j+1) of a (around+1) x (along+1) vertex grid, split along alternating diagonals,
// counter-clockwise when the grid's (i, j) axes are counter-clockwise.
Eigen::MatrixXi grid_triangles(int around, int along) {
  Eigen::MatrixXi F(2 * around * along, 3);
  int f = 0;
  const auto id = [&](int i, int j) { return j * (around + 1) + i; };
  for (int j = 0; j < along; ++j) {
    for (int i = 0; i < around; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) {
        F.row(f++) << a, b, c;
        F.row(f++) << a, c, d;
      } else {
        F.row(f++) << a, b, d;
        F.row(f++) << b, c, d;
      }
    }
  }
  return F;
}

}  // namespace

DevelopablePatch cylinder_patch(double radius_mm, double sweep_deg, double length_mm, int around, int along) {
  DevelopablePatch patch;
  const int count = (around + 1) * (along + 1);
  patch.mesh.V.resize(count, 3);
  patch.development.resize(count, 2);
  const double sweep = sweep_deg * std::numbers::pi / 180.0;
  std::vector<double> chord_position(around + 1, 0.0);
  for (int i = 1; i <= around; ++i) {
    const double gap = sweep * (warped(i, around) - warped(i - 1, around));
    chord_position[i] = chord_position[i - 1] + 2.0 * radius_mm * std::sin(0.5 * gap);
  }
  for (int j = 0; j <= along; ++j) {
    const double z = length_mm * warped(j, along);
    for (int i = 0; i <= around; ++i) {
      const double angle = sweep * warped(i, around);
      const int v = j * (around + 1) + i;
      patch.mesh.V.row(v) << radius_mm * std::cos(angle), radius_mm * std::sin(angle), z;
      patch.development.row(v) << chord_position[i], z;
    }
  }
  // Grid axes (angle, z) with outward normals: angle x z points outward, so faces are counter-clockwise.
  patch.mesh.F = grid_triangles(around, along);
  return patch;
}

DevelopablePatch cone_patch(double half_angle_deg, double sweep_deg, double slant_min_mm, double slant_max_mm,
                            int around, int along) {
  DevelopablePatch patch;
  const int count = (around + 1) * (along + 1);
  patch.mesh.V.resize(count, 3);
  patch.development.resize(count, 2);
  const double half_angle = half_angle_deg * std::numbers::pi / 180.0;
  const double sweep = sweep_deg * std::numbers::pi / 180.0;
  std::vector<Eigen::Vector3d> ruling(around + 1);
  std::vector<double> ray_angle(around + 1, 0.0);
  for (int i = 0; i <= around; ++i) {
    const double angle = sweep * warped(i, around);
    ruling[i] = Eigen::Vector3d(std::sin(half_angle) * std::cos(angle), std::sin(half_angle) * std::sin(angle),
                                std::cos(half_angle));
    if (i > 0) ray_angle[i] = ray_angle[i - 1] + std::acos(std::clamp(ruling[i].dot(ruling[i - 1]), -1.0, 1.0));
  }
  for (int j = 0; j <= along; ++j) {
    const double s = slant_min_mm + (slant_max_mm - slant_min_mm) * warped(j, along);
    for (int i = 0; i <= around; ++i) {
      const int v = j * (around + 1) + i;
      patch.mesh.V.row(v) = s * ruling[i].transpose();
      // Rays turn clockwise as the angle grows so that (angle, slant) stays counter-clockwise in 2D.
      patch.development.row(v) << s * std::cos(-ray_angle[i]), s * std::sin(-ray_angle[i]);
    }
  }
  patch.mesh.F = grid_triangles(around, along);
  return patch;
}

TriMesh read_off(const std::filesystem::path& path, double scale) {
  std::ifstream in(path);
  std::string magic;
  int vertex_count = 0, face_count = 0, edge_count = 0;
  if (!(in >> magic) || magic != "OFF" || !(in >> vertex_count >> face_count >> edge_count)) {
    throw EngineError("cannot read OFF file " + path.string());
  }
  TriMesh mesh;
  mesh.V.resize(vertex_count, 3);
  mesh.F.resize(face_count, 3);
  for (int v = 0; v < vertex_count; ++v) {
    in >> mesh.V(v, 0) >> mesh.V(v, 1) >> mesh.V(v, 2);
  }
  for (int f = 0; f < face_count; ++f) {
    int corners = 0;
    in >> corners >> mesh.F(f, 0) >> mesh.F(f, 1) >> mesh.F(f, 2);
    if (corners != 3) throw EngineError("OFF file " + path.string() + " has a face that is not a triangle");
  }
  if (!in) throw EngineError("OFF file " + path.string() + " is truncated");
  mesh.V *= scale;
  return mesh;
}

TriMesh subdivide_midpoint(const TriMesh& mesh) {
  std::map<std::pair<int, int>, int> midpoint_of;
  std::vector<Eigen::RowVector3d> points;
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) points.push_back(mesh.V.row(v));
  const auto midpoint = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto [it, inserted] = midpoint_of.try_emplace({key.first, key.second}, static_cast<int>(points.size()));
    if (inserted) points.push_back(0.5 * (mesh.V.row(a) + mesh.V.row(b)));
    return it->second;
  };
  TriMesh out;
  out.F.resize(4 * mesh.F.rows(), 3);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const int a = mesh.F(f, 0), b = mesh.F(f, 1), c = mesh.F(f, 2);
    const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    out.F.row(4 * f) << a, ab, ca;
    out.F.row(4 * f + 1) << ab, b, bc;
    out.F.row(4 * f + 2) << ca, bc, c;
    out.F.row(4 * f + 3) << ab, bc, ca;
  }
  out.V.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t v = 0; v < points.size(); ++v) out.V.row(static_cast<Eigen::Index>(v)) = points[v];
  return out;
}

namespace {

// moving after the rotation and translation (no reflection, no scaling) that best fit it onto target.
Eigen::MatrixXd rigidly_aligned(const Eigen::MatrixXd& moving, const Eigen::MatrixXd& target) {
  const Eigen::RowVector2d moving_mean = moving.colwise().mean(), target_mean = target.colwise().mean();
  const Eigen::MatrixXd P = moving.rowwise() - moving_mean, Q = target.rowwise() - target_mean;
  const Eigen::Matrix2d H = P.transpose() * Q;
  const Eigen::JacobiSVD<Eigen::Matrix2d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix2d D = Eigen::Matrix2d::Identity();
  D(1, 1) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  const Eigen::Matrix2d R = svd.matrixV() * D * svd.matrixU().transpose();
  return (P * R.transpose()).rowwise() + target_mean;
}

}  // namespace

double max_distance_after_rigid_alignment(const Eigen::MatrixXd& moving, const Eigen::MatrixXd& target) {
  return (rigidly_aligned(moving, target) - target).rowwise().norm().maxCoeff();
}

double rms_distance_after_rigid_alignment(const Eigen::MatrixXd& moving, const Eigen::MatrixXd& target) {
  return std::sqrt((rigidly_aligned(moving, target) - target).rowwise().squaredNorm().mean());
}

// Spherical cap of radius_mm up to polar angle cap_deg, as a ring grid with a fan at the pole.
TriMesh square_10mm() {
  TriMesh square;
  square.V.resize(4, 3);
  square.V << 0, 0, 0, 10, 0, 0, 10, 10, 0, 0, 10, 0;
  square.F.resize(2, 3);
  square.F << 0, 1, 2, 0, 2, 3;
  return square;
}

TriMesh spherical_cap(double radius_mm, double cap_deg, int rings, int around) {
  TriMesh mesh;
  mesh.V.resize(1 + rings * around, 3);
  mesh.V.row(0) << 0.0, 0.0, radius_mm;
  for (int r = 1; r <= rings; ++r) {
    const double polar = cap_deg * std::numbers::pi / 180.0 * r / rings;
    for (int a = 0; a < around; ++a) {
      const double azimuth = 2.0 * std::numbers::pi * (a + 0.5 * (r % 2)) / around;
      mesh.V.row(1 + (r - 1) * around + a) << radius_mm * std::sin(polar) * std::cos(azimuth),
          radius_mm * std::sin(polar) * std::sin(azimuth), radius_mm * std::cos(polar);
    }
  }
  std::vector<Eigen::Vector3i> faces;
  for (int a = 0; a < around; ++a) faces.emplace_back(0, 1 + a, 1 + (a + 1) % around);
  for (int r = 1; r < rings; ++r) {
    for (int a = 0; a < around; ++a) {
      const int i0 = 1 + (r - 1) * around + a, i1 = 1 + (r - 1) * around + (a + 1) % around;
      const int o0 = 1 + r * around + a, o1 = 1 + r * around + (a + 1) % around;
      faces.emplace_back(i0, o0, o1);
      faces.emplace_back(i0, o1, i1);
    }
  }
  mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f) mesh.F.row(static_cast<Eigen::Index>(f)) = faces[f].transpose();
  return mesh;
}

TriMesh helicoidal_ramp(double r_in_mm, double r_out_mm, double sweep_deg, double pitch_mm, int radial, int around) {
  TriMesh mesh;
  mesh.V.resize((radial + 1) * (around + 1), 3);
  const double sweep_rad = sweep_deg * std::numbers::pi / 180.0;
  for (int j = 0; j <= around; ++j) {
    const double theta = sweep_rad * j / around;
    for (int i = 0; i <= radial; ++i) {
      const double r = r_in_mm + (r_out_mm - r_in_mm) * i / radial;
      mesh.V.row(j * (radial + 1) + i) << r * std::cos(theta), r * std::sin(theta),
          pitch_mm * theta / (2.0 * std::numbers::pi);
    }
  }
  mesh.F.resize(2 * radial * around, 3);
  int f = 0;
  for (int j = 0; j < around; ++j) {
    for (int i = 0; i < radial; ++i) {
      const int a = j * (radial + 1) + i, b = a + 1, c = a + radial + 2, d = a + radial + 1;
      if ((i + j) % 2 == 0) {
        mesh.F.row(f++) << a, b, c;
        mesh.F.row(f++) << a, c, d;
      } else {
        mesh.F.row(f++) << a, b, d;
        mesh.F.row(f++) << b, c, d;
      }
    }
  }
  return mesh;
}

}  // namespace lastcut::testing
