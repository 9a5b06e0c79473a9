#pragma once
// The last as a quad control mesh and its bicubic Bezier surface (engine/subdiv), the alternative to
// marching tetrahedra + isotropic remeshing (LastSurface::Bezier).
//
// Control mesh: the surface of a box of nx x ny x nz quads (a cube sphere, eight valence-3 vertices at
// the box corners, all others valence 4), each lattice point sent along its equi-angular cube-map
// direction, stretched to the last's extent, from one point inside the last to where the ray leaves
// the solid (bisection on LastShape::value). The control points are then moved so that the limit
// positions of the surface (the Bezier patch corners) lie on the solid's surface: a few fixed-point
// steps v <- v + (project(P(v)) - P(v)). The Bezier surface passes through the shape at every control
// vertex and is C2 between them away from the eight corners; it rounds features narrower than the
// control spacing (the 2 mm fillet of the top cut becomes ~ one control spacing wide).
#include "engine/core/tri_mesh.hpp"
#include "engine/lastgen/last_shape.hpp"
#include "engine/subdiv/quad_mesh.hpp"

namespace lastcut {

// About `control_quads` quads (box proportional to the last), outward, closed. Throws EngineError
// when a ray does not leave the solid or the centre is not inside.
QuadMesh last_control_mesh(const LastShape& shape, const LastParams& params, int control_quads);

// The detail n and control size for ~ target_triangles triangles (2 n^2 per control quad): n = 4
// (the Catmull-Clark-like density) for the default 50k triangles, fewer for small meshes, at most 8.
int bezier_detail_for(int target_triangles);

// The triangulated Bezier surface of the last (samples spread evenly at the eight extraordinary
// vertices, SampleSpread::EvenAtExtraordinary), 2 F n^2 triangles with F within a few % of
// target_triangles / (2 n^2) (the box's sides are whole numbers of quads).
TriMesh bezier_last_surface(const LastShape& shape, const LastParams& params);

}  // namespace lastcut
