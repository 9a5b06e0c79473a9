#pragma once
// Quad control meshes for the subdivision tests, built without engine/subdiv.
#include <Eigen/Core>
#include <cstdint>

#include "engine/subdiv/quad_mesh.hpp"

namespace lastcut::test {

// A cube of m x m quads per side pushed onto a wobbly sphere of radius ~ radius_mm: closed,
// 6 m^2 quads, eight extraordinary vertices (valence 3) at the cube's corners, all others valence 4.
QuadMesh cube_sphere(int m, double radius_mm);

// A pentagonal prism of 20 quads (each cap split into 5 quads around its centre, each side into 2)
// pushed onto a sphere of radius radius_mm: closed, valence 5 at the two cap centres, 3 at the ten
// prism corners, 4 at the ten edge midpoints.
QuadMesh pentagon_prism(double radius_mm);

// An open grid of nx x ny unit quads (mm) with smooth pseudo-random heights z(x, y) from `seed`;
// face (i, j) is quad i + nx j with corners (i,j), (i+1,j), (i+1,j+1), (i,j+1), so its u runs along x.
QuadMesh height_grid(int nx, int ny, uint64_t seed);

// True when every corner of face q has valence 4 in the closed mesh (counted from Q directly).
bool face_is_regular(const QuadMesh& mesh, int q);

}  // namespace lastcut::test
