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

// Where the rays point (mm, boxes containing the centre): the lattice is split at the centre in the
// proportions of [low, high] and each lattice direction stretched to that box's sides, which decides which
// face of the cube looks at which part of the last. Above the centre the x and y stretch blend linearly
// (with the cube's z coordinate, 0 at the centre, 1 on the top face) into those of [top_low, top_high],
// so that the top face can look at a smaller region than the bottom face.
struct RayBox {
  Eigen::Vector3d low, high, top_low, top_high;
};

// Throws EngineError when `centre_mm` is not inside the solid or a ray does not leave it.
CubeSphere cast_cube_sphere(const LastShape& shape, const Eigen::Vector3d& centre_mm, const RayBox& box,
                            const std::array<int, 3>& cells);

// The same box lattice cast from a spine instead of one point: the middle share of the box's x lattice
// (|cube x| <= kSpineShare) casts from points of a segment along the last (0.15 to 0.85 of its length,
// at the middle of its section) straight across, to the section's half extents; the rest fans out from
// the segment's ends over the heel and the toe. Rays from one point give cells small where the surface
// is near it (the instep) and large far off (the toe: 90 : 1 in area); rays from a spine give cells
// about as long along the last everywhere. The x stations of the lattice are then moved so that every
// slab between two of them holds the same area (measured on a first cast): sections have the same
// number of cells around, so evenly spaced stations gave the tall instep sections cells twice the toe's.
// Throws EngineError when a ray does not leave the solid.
CubeSphere cast_along_spine(const LastShape& shape, const LastParams& params, const std::array<int, 3>& cells);

}  // namespace lastcut
