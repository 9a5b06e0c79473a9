#include "engine/core/tri_mesh.hpp"

#include <Eigen/Geometry>
#include <cstdio>
#include <memory>

#include "engine/core/engine_error.hpp"

namespace lastcut {

Eigen::VectorXd triangle_areas(const TriMesh& mesh) {
  Eigen::VectorXd areas(mesh.F.rows());
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0));
    const Eigen::Vector3d b = mesh.V.row(mesh.F(f, 1));
    const Eigen::Vector3d c = mesh.V.row(mesh.F(f, 2));
    areas(f) = 0.5 * (b - a).cross(c - a).norm();
  }
  return areas;
}

Eigen::MatrixXd triangle_normals(const TriMesh& mesh) {
  Eigen::MatrixXd normals(mesh.F.rows(), 3);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0));
    const Eigen::Vector3d b = mesh.V.row(mesh.F(f, 1));
    const Eigen::Vector3d c = mesh.V.row(mesh.F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double length = n.norm();
    normals.row(f) = length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
  }
  return normals;
}

double surface_area(const TriMesh& mesh) { return triangle_areas(mesh).sum(); }

Eigen::Vector3d bounding_box_size(const TriMesh& mesh) {
  if (mesh.V.rows() == 0) return Eigen::Vector3d::Zero();
  return mesh.V.colwise().maxCoeff() - mesh.V.colwise().minCoeff();
}

namespace {

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

File open_for_writing(const std::filesystem::path& path) {
  File file(std::fopen(path.c_str(), "w"));
  if (!file) throw EngineError("cannot write " + path.string());
  return file;
}

void write_faces(std::FILE* file, const Eigen::MatrixXi& F) {
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    std::fprintf(file, "f %d %d %d\n", F(f, 0) + 1, F(f, 1) + 1, F(f, 2) + 1);
}

}  // namespace

void write_obj(const std::filesystem::path& path, const TriMesh& mesh) {
  File file = open_for_writing(path);
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    std::fprintf(file.get(), "v %.6f %.6f %.6f\n", mesh.V(v, 0), mesh.V(v, 1), mesh.V(v, 2));
  write_faces(file.get(), mesh.F);
}

void write_obj_2d(const std::filesystem::path& path, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F) {
  File file = open_for_writing(path);
  for (Eigen::Index v = 0; v < UV.rows(); ++v) std::fprintf(file.get(), "v %.6f %.6f 0\n", UV(v, 0), UV(v, 1));
  write_faces(file.get(), F);
}

}  // namespace lastcut
