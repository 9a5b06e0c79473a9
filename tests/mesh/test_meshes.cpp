#include "test_meshes.hpp"

#include <Eigen/Geometry>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace lastcut::test {

TriMesh box_mesh(const Eigen::Vector3d& low, const Eigen::Vector3d& high, int n) {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3i> faces;
  // Each side: origin corner and two edge directions whose cross product points outward.
  const Eigen::Vector3d size = high - low;
  struct Side {
    Eigen::Vector3d origin, u, v;
  };
  const Eigen::Vector3d ex(size.x(), 0, 0), ey(0, size.y(), 0), ez(0, 0, size.z());
  const std::vector<Side> sides{
      {low, ey, ex}, {low + ez, ex, ey},            // bottom (-z), top (+z)
      {low, ex, ez}, {low + ey, ez, ex},            // front (-y), back (+y)
      {low, ez, ey}, {low + ex, ey, ez},            // left (-x), right (+x)
  };
  for (const Side& side : sides) {
    const int base = static_cast<int>(points.size());
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) points.push_back(side.origin + side.u * (double(i) / n) + side.v * (double(j) / n));
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = base + j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
        faces.emplace_back(a, b, d);
        faces.emplace_back(a, d, c);
      }
  }
  // Merge the shared corners/edges between sides so the box is one closed surface.
  TriMesh mesh;
  std::vector<int> index(points.size());
  std::vector<Eigen::Vector3d> unique;
  for (size_t p = 0; p < points.size(); ++p) {
    int found = -1;
    for (size_t q = 0; q < unique.size(); ++q)
      if ((unique[q] - points[p]).norm() < 1e-9) {
        found = static_cast<int>(q);
        break;
      }
    if (found < 0) {
      found = static_cast<int>(unique.size());
      unique.push_back(points[p]);
    }
    index[p] = found;
  }
  mesh.V.resize(static_cast<Eigen::Index>(unique.size()), 3);
  for (size_t q = 0; q < unique.size(); ++q) mesh.V.row(static_cast<Eigen::Index>(q)) = unique[q].transpose();
  mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f)
    mesh.F.row(static_cast<Eigen::Index>(f)) << index[static_cast<size_t>(faces[f].x())], index[static_cast<size_t>(faces[f].y())],
        index[static_cast<size_t>(faces[f].z())];
  return mesh;
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void write_obj_raw(const std::filesystem::path& path, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  std::ofstream out(path);
  out.precision(17);
  for (Eigen::Index v = 0; v < V.rows(); ++v) out << "v " << V(v, 0) << ' ' << V(v, 1) << ' ' << V(v, 2) << '\n';
  for (Eigen::Index f = 0; f < F.rows(); ++f) out << "f " << F(f, 0) + 1 << ' ' << F(f, 1) + 1 << ' ' << F(f, 2) + 1 << '\n';
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void write_ascii_stl_raw(const std::filesystem::path& path, const TriMesh& mesh) {
  std::ofstream out(path);
  out << "solid test\n";
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    out << "  facet normal 0 0 0\n    outer loop\n";
    for (int c = 0; c < 3; ++c)
      out << "      vertex " << mesh.V(mesh.F(f, c), 0) << ' ' << mesh.V(mesh.F(f, c), 1) << ' ' << mesh.V(mesh.F(f, c), 2) << '\n';
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid test\n";
}

void write_ascii_ply_raw(const std::filesystem::path& path, const TriMesh& mesh) {
  std::ofstream out(path);
  out.precision(9);
  out << "ply\nformat ascii 1.0\ncomment test\nelement vertex " << mesh.V.rows()
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << mesh.F.rows()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) out << mesh.V(v, 0) << ' ' << mesh.V(v, 1) << ' ' << mesh.V(v, 2) << '\n';
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) out << "3 " << mesh.F(f, 0) << ' ' << mesh.F(f, 1) << ' ' << mesh.F(f, 2) << '\n';
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void write_binary_stl_raw(const std::filesystem::path& path, const TriMesh& mesh, long claimed_triangles) {
  std::ofstream out(path, std::ios::binary);
  char header[80] = "test binary STL";
  out.write(header, 80);
  const uint32_t count = static_cast<uint32_t>(claimed_triangles >= 0 ? claimed_triangles : mesh.F.rows());
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    float values[12] = {0, 0, 0};
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) values[3 + 3 * c + k] = static_cast<float>(mesh.V(mesh.F(f, c), k));
    out.write(reinterpret_cast<const char*>(values), sizeof values);
    const uint16_t attribute = 0;
    out.write(reinterpret_cast<const char*>(&attribute), 2);
  }
}

}  // namespace lastcut::test
