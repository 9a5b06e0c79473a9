#include "engine/core/tri_mesh.hpp"

#include <Eigen/Geometry>
#include <fstream>

#include "engine/core/decimal_text.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/core/text_sink.hpp"

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

Eigen::MatrixXd vertex_normals(const TriMesh& mesh) {
  Eigen::MatrixXd normals = Eigen::MatrixXd::Zero(mesh.V.rows(), 3);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const Eigen::RowVector3d area_normal = (b - a).cross(c - a).transpose();  // its length: twice the area
    for (int corner = 0; corner < 3; ++corner) normals.row(mesh.F(f, corner)) += area_normal;
  }
  for (Eigen::Index v = 0; v < normals.rows(); ++v) {
    const double length = normals.row(v).norm();
    if (length > 0.0) normals.row(v) /= length;
  }
  return normals;
}

double surface_area(const TriMesh& mesh) { return triangle_areas(mesh).sum(); }

Eigen::Vector3d bounding_box_size(const TriMesh& mesh) {
  if (mesh.V.rows() == 0) return Eigen::Vector3d::Zero();
  return mesh.V.colwise().maxCoeff() - mesh.V.colwise().minCoeff();
}

namespace {

std::ofstream open_for_writing(const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw EngineError("cannot write " + path.string());
  return out;
}

// `columns` coordinates of each vertex with 6 decimals (1 nm in mm), then z = 0 for 2D positions,
// then the triangles with 1-based indices.
void write_obj_text(const std::filesystem::path& path, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  std::ofstream out = open_for_writing(path);
  {
    TextSink sink(out);
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
      sink.text() += 'v';
      for (Eigen::Index c = 0; c < V.cols(); ++c) {
        sink.text() += ' ';
        append_fixed(sink.text(), V(v, c), 6);
      }
      if (V.cols() == 2) sink.text() += " 0";
      sink.end_line();
    }
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
      sink.text() += 'f';
      for (int c = 0; c < 3; ++c) {
        sink.text() += ' ';
        append_integer(sink.text(), F(f, c) + 1);
      }
      sink.end_line();
    }
  }
  out.flush();
  if (!out) throw EngineError("cannot write " + path.string() + " (disk full?)");
}

}  // namespace

void write_obj(const std::filesystem::path& path, const TriMesh& mesh) { write_obj_text(path, mesh.V, mesh.F); }

void write_obj_2d(const std::filesystem::path& path, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F) {
  write_obj_text(path, UV, F);
}

}  // namespace lastcut
