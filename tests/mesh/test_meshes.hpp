#pragma once
// Small meshes and raw file writers for the intake tests. The writers are written here, not
// taken from engine/mesh, so that bad files can be made on purpose and good files do not depend
// on the code under test.
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/tri_mesh.hpp"
#include "tests/support/temp_dir.hpp"  // TempDir for the intake tests

namespace lastcut::test {

// Closed axis-aligned box from `low` to `high` (mm), each face split into n x n quads
// (2 n^2 triangles per side), outward oriented.
TriMesh box_mesh(const Eigen::Vector3d& low, const Eigen::Vector3d& high, int n);

void write_text(const std::filesystem::path& path, const std::string& text);
// OBJ with the given vertices and faces (0-based in F, written 1-based).
void write_obj_raw(const std::filesystem::path& path, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);
// ASCII STL (one facet per triangle).
void write_ascii_stl_raw(const std::filesystem::path& path, const TriMesh& mesh);
// ASCII PLY ("format ascii 1.0"): float x y z per vertex, a "3 a b c" list per face.
void write_ascii_ply_raw(const std::filesystem::path& path, const TriMesh& mesh);
// Binary STL whose header claims `claimed_triangles` (defaults to the real count).
void write_binary_stl_raw(const std::filesystem::path& path, const TriMesh& mesh, long claimed_triangles = -1);

}  // namespace lastcut::test
