#pragma once
// The last as one closed quad control mesh whose bicubic Bezier surface (engine/subdiv) rounds the top cut
// (the benchmarks' and reflection pictures' subject; the generator's default keeps the cut sharp with
// last_side_mesh.hpp).
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

}  // namespace lastcut
