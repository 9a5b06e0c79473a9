#pragma once
// The quad layout both Bezier control meshes of the last start from: the surface of a box of
// nx x ny x nz quads (a cube sphere: eight valence-3 vertices at the box corners, all others valence 4),
// each lattice point sent along its equi-angular cube-map direction, stretched to the box [low, high],
// from a point inside the last to where the ray leaves the solid (bisection on LastShape::value).
#include <array>
#include <vector>

#include "engine/lastgen/last_shape.hpp"
#include "engine/subdiv/quad_mesh.hpp"

namespace lastcut {

struct CubeSphere {
  QuadMesh mesh;                               // closed, counter-clockwise seen from outside, mm
  std::vector<std::array<int, 3>> lattice;     // #V: the vertex's box lattice point (0..cells)
  // Per quad: the box face (axis 0..2, on the high side or not) and its cell (i, j) along the
  // axes (axis + 1) % 3 and (axis + 2) % 3.
  std::vector<std::array<int, 4>> face_cell;   // #Q: {axis, high side 0/1, i, j}
};

// Cells per axis for about `control_quads` quads on a box proportional to `extent_mm` (at least 2 each).
std::array<int, 3> cube_cells_for(const Eigen::Vector3d& extent_mm, int control_quads);

// The rays are stretched to the box [low_mm, high_mm] (which must contain centre_mm): the box's sides
// decide which face of the cube looks at which part of the last. Throws EngineError when `centre_mm`
// is not inside the solid or a ray does not leave it.
CubeSphere cast_cube_sphere(const LastShape& shape, const Eigen::Vector3d& centre_mm, const Eigen::Vector3d& low_mm,
                            const Eigen::Vector3d& high_mm, const std::array<int, 3>& cells);

}  // namespace lastcut
