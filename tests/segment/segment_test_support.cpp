#include "segment_test_support.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>

namespace lastcut::test {

TriMesh read_obj_scaled(const std::filesystem::path& path, double scale) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> faces;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string tag;
    fields >> tag;
    if (tag == "v") {
      Eigen::Vector3d p;
      fields >> p.x() >> p.y() >> p.z();
      vertices.push_back(p * scale);
    } else if (tag == "f") {
      Eigen::Vector3i f;
      for (int k = 0; k < 3; ++k) {
        std::string corner;
        fields >> corner;
        f(k) = std::stoi(corner.substr(0, corner.find('/'))) - 1;
      }
      faces.push_back(f);
    }
  }
  TriMesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t i = 0; i < vertices.size(); ++i) mesh.V.row(static_cast<Eigen::Index>(i)) = vertices[i].transpose();
  for (std::size_t i = 0; i < faces.size(); ++i) mesh.F.row(static_cast<Eigen::Index>(i)) = faces[i].transpose();
  return mesh;
}

std::vector<std::vector<int>> boundary_loops_of(const TriMesh& mesh) {
  std::set<std::pair<int, int>> directed;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) directed.emplace(mesh.F(f, k), mesh.F(f, (k + 1) % 3));
  std::map<int, int> next;
  for (const auto& [a, b] : directed)
    if (!directed.contains({b, a})) next[a] = b;
  std::set<int> seen;
  std::vector<std::vector<int>> loops;
  for (const auto& [start, unused] : next) {
    if (seen.contains(start)) continue;
    std::vector<int> loop;
    for (int v = start; !seen.contains(v) && next.contains(v); v = next.at(v)) {
      seen.insert(v);
      loop.push_back(v);
    }
    loops.push_back(loop);
  }
  return loops;
}

long long euler_characteristic_of(const TriMesh& mesh) {
  std::set<std::pair<int, int>> edges;
  std::set<int> used;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      edges.emplace(std::min(a, b), std::max(a, b));
      used.insert(a);
    }
  return static_cast<long long>(used.size()) - static_cast<long long>(edges.size()) + mesh.F.rows();
}

namespace {

// Points every step_mm along the closed polyline, with the arc length at each.
std::vector<Eigen::Vector3d> resample_closed(const std::vector<Eigen::Vector3d>& points, double step_mm) {
  std::vector<Eigen::Vector3d> samples;
  double carried = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d a = points[i], b = points[(i + 1) % points.size()];
    const double length = (b - a).norm();
    double s = carried;
    while (s < length) {
      samples.push_back(a + (b - a) * (s / length));
      s += step_mm;
    }
    carried = s - length;
  }
  return samples;
}

}  // namespace

BoundarySmoothness boundary_smoothness(const TriMesh& mesh, const std::vector<int>& boundary,
                                       const std::vector<int>& corners, double corner_clearance_mm, double kStepMm) {
  constexpr int kAverageHalfWindow = 2;  // +-2 samples = +-4 mm
  std::vector<Eigen::Vector3d> points;
  for (int v : boundary) points.emplace_back(mesh.V.row(v).transpose());
  const std::vector<Eigen::Vector3d> samples = resample_closed(points, kStepMm);
  const auto n = static_cast<int>(samples.size());
  auto sample = [&](int i) { return samples[static_cast<std::size_t>(((i % n) + n) % n)]; };
  auto near_corner = [&](const Eigen::Vector3d& p) {
    return std::any_of(corners.begin(), corners.end(), [&](int c) {
      return (p - Eigen::Vector3d(mesh.V.row(c).transpose())).norm() < corner_clearance_mm;
    });
  };
  BoundarySmoothness result;
  double boundary_length = 0.0, averaged_length = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) boundary_length += (points[(i + 1) % points.size()] - points[i]).norm();
  std::vector<Eigen::Vector3d> averaged(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int k = -kAverageHalfWindow; k <= kAverageHalfWindow; ++k) sum += sample(i + k);
    // Corners are kept where they are: averaging across them would cut them off.
    averaged[static_cast<std::size_t>(i)] = near_corner(sample(i)) ? sample(i) : Eigen::Vector3d(sum / (2 * kAverageHalfWindow + 1));
  }
  for (int i = 0; i < n; ++i) averaged_length += (averaged[static_cast<std::size_t>((i + 1) % n)] - averaged[static_cast<std::size_t>(i)]).norm();
  result.staircase_ratio = boundary_length / averaged_length;
  for (int i = 0; i < n; ++i) {
    if (near_corner(sample(i))) continue;
    const Eigen::Vector3d in = sample(i) - sample(i - 1), out = sample(i + 1) - sample(i);
    const double cosine = std::clamp(in.dot(out) / (in.norm() * out.norm()), -1.0, 1.0);
    result.max_turning_deg = std::max(result.max_turning_deg, std::acos(cosine) * 180.0 / std::numbers::pi);
  }
  return result;
}

Eigen::VectorXd face_elevation_rad(const TriMesh& mesh) {
  const Eigen::MatrixXd normals = triangle_normals(mesh);
  Eigen::VectorXd elevation(normals.rows());
  for (Eigen::Index f = 0; f < normals.rows(); ++f) elevation(f) = std::asin(std::clamp(normals(f, 2), -1.0, 1.0));
  return elevation;
}

TriMesh uv_sphere(double radius_mm, int rings, int segments) {
  TriMesh mesh;
  mesh.V.resize(2 + (rings - 1) * segments, 3);
  mesh.V.row(0) = Eigen::RowVector3d(0, 0, radius_mm);
  mesh.V.row(1) = Eigen::RowVector3d(0, 0, -radius_mm);
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double theta = std::numbers::pi * r / rings, phi = 2.0 * std::numbers::pi * s / segments;
      mesh.V.row(2 + (r - 1) * segments + s) =
          radius_mm * Eigen::RowVector3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    }
  auto ring_vertex = [&](int r, int s) { return 2 + (r - 1) * segments + ((s % segments) + segments) % segments; };
  std::vector<Eigen::RowVector3i> faces;
  for (int s = 0; s < segments; ++s) {
    faces.emplace_back(0, ring_vertex(1, s), ring_vertex(1, s + 1));
    faces.emplace_back(1, ring_vertex(rings - 1, s + 1), ring_vertex(rings - 1, s));
    for (int r = 1; r < rings - 1; ++r) {
      faces.emplace_back(ring_vertex(r, s), ring_vertex(r + 1, s), ring_vertex(r + 1, s + 1));
      faces.emplace_back(ring_vertex(r, s), ring_vertex(r + 1, s + 1), ring_vertex(r, s + 1));
    }
  }
  mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t i = 0; i < faces.size(); ++i) mesh.F.row(static_cast<Eigen::Index>(i)) = faces[i];
  return mesh;
}

TriMesh midpoint_subdivided(const TriMesh& mesh, int levels) {
  TriMesh current = mesh;
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    std::vector<Eigen::RowVector3d> vertices;
    for (Eigen::Index v = 0; v < current.V.rows(); ++v) vertices.push_back(current.V.row(v));
    auto middle = [&](int a, int b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto [it, inserted] = midpoint.emplace(key, static_cast<int>(vertices.size()));
      if (inserted) vertices.push_back(0.5 * (current.V.row(a) + current.V.row(b)));
      return it->second;
    };
    TriMesh finer;
    finer.F.resize(4 * current.F.rows(), 3);
    for (Eigen::Index f = 0; f < current.F.rows(); ++f) {
      const int a = current.F(f, 0), b = current.F(f, 1), c = current.F(f, 2);
      const int ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
      finer.F.row(4 * f) = Eigen::RowVector3i(a, ab, ca);
      finer.F.row(4 * f + 1) = Eigen::RowVector3i(ab, b, bc);
      finer.F.row(4 * f + 2) = Eigen::RowVector3i(ca, bc, c);
      finer.F.row(4 * f + 3) = Eigen::RowVector3i(ab, bc, ca);
    }
    finer.V.resize(static_cast<Eigen::Index>(vertices.size()), 3);
    for (std::size_t i = 0; i < vertices.size(); ++i) finer.V.row(static_cast<Eigen::Index>(i)) = vertices[i];
    current = finer;
  }
  return current;
}

TriMesh without_faces_around(const TriMesh& mesh, const std::vector<int>& vertices) {
  const std::set<int> removed(vertices.begin(), vertices.end());
  std::vector<Eigen::RowVector3i> kept;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    if (!removed.contains(mesh.F(f, 0)) && !removed.contains(mesh.F(f, 1)) && !removed.contains(mesh.F(f, 2)))
      kept.push_back(mesh.F.row(f));
  TriMesh result;
  result.V = mesh.V;
  result.F.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (std::size_t i = 0; i < kept.size(); ++i) result.F.row(static_cast<Eigen::Index>(i)) = kept[i];
  return result;
}

}  // namespace lastcut::test
