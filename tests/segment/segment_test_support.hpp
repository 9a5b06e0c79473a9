#pragma once
// Shared checks for the orientation and segmentation tests: reading the reference OBJ, the
// topology of a half (boundary loops, Euler characteristic) and measurable smoothness of its
// boundary. Written independently of the engine code they check.
#include <Eigen/Core>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "engine/core/tri_mesh.hpp"

namespace lastcut::test {

// Wavefront OBJ ("v x y z", "f a b c" with optional /vt/vn), coordinates multiplied by scale.
TriMesh read_obj_scaled(const std::filesystem::path& path, double scale);

// Boundary loops (vertex indices in edge order) and Euler characteristic V - E + F.
std::vector<std::vector<int>> boundary_loops_of(const TriMesh& mesh);
long long euler_characteristic_of(const TriMesh& mesh);

struct BoundarySmoothness {
  double max_turning_deg = 0;  // largest turn between consecutive 2 mm chords, away from the corners
  double staircase_ratio = 0;  // boundary length / length of the same boundary averaged over +-4 mm
};

// boundary: one closed loop of mesh vertices; corners: vertex indices where the boundary may turn
// sharply (the landmarks); turns within corner_clearance_mm of a corner are ignored.
BoundarySmoothness boundary_smoothness(const TriMesh& mesh, const std::vector<int>& boundary,
                                       const std::vector<int>& corners, double corner_clearance_mm, double step_mm = 2.0);

// Elevation (rad) of each face normal above the XY plane.
Eigen::VectorXd face_elevation_rad(const TriMesh& mesh);

// A closed UV sphere (radius_mm, rings x segments), outward faces.
TriMesh uv_sphere(double radius_mm, int rings, int segments);

// 1-to-4 midpoint subdivision (the surface is unchanged, only finer), `levels` times.
TriMesh midpoint_subdivided(const TriMesh& mesh, int levels);

// The mesh without the faces touching the given vertices (opens a hole around each).
TriMesh without_faces_around(const TriMesh& mesh, const std::vector<int>& vertices);

}  // namespace lastcut::test
