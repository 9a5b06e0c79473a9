#pragma once
// TriMesh: the engine's triangle mesh, in the libigl layout.
//   V  #V x 3 double, vertex positions in millimetres
//   F  #F x 3 int, vertex indices, counter-clockwise seen from outside (outward normals)
// OpenMesh is used where topology is needed (reading, repair); TriMesh is what modules exchange.
#include <Eigen/Core>
#include <filesystem>

namespace lastcut {

struct TriMesh {
  Eigen::MatrixXd V;  // #V x 3, mm
  Eigen::MatrixXi F;  // #F x 3

  int vertex_count() const { return static_cast<int>(V.rows()); }
  int triangle_count() const { return static_cast<int>(F.rows()); }
};

// Area of each triangle (#F, mm^2).
Eigen::VectorXd triangle_areas(const TriMesh& mesh);
// Unit normal of each triangle (#F x 3); zero rows for degenerate triangles.
Eigen::MatrixXd triangle_normals(const TriMesh& mesh);
// Unit normal of each vertex (#V x 3): the area-weighted mean of its triangles' normals; zero rows
// for vertices on no triangle or where the normals cancel.
Eigen::MatrixXd vertex_normals(const TriMesh& mesh);
// Total surface area (mm^2).
double surface_area(const TriMesh& mesh);
// Axis-aligned bounding box extent (max - min) per axis (mm).
Eigen::Vector3d bounding_box_size(const TriMesh& mesh);

// Wavefront OBJ, "v x y z" and "f a b c" (1-based). Throws EngineError when the file cannot be written.
void write_obj(const std::filesystem::path& path, const TriMesh& mesh);
// OBJ with 2D vertices written as "v u v 0", same faces: the flattened twin of a 3D OBJ.
void write_obj_2d(const std::filesystem::path& path, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F);

}  // namespace lastcut
