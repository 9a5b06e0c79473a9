#pragma once
// The Bezier surface of the last with a sharp top cut (LastSurface::Bezier, `lastcut generate --surface bezier`):
// the C2 Bezier side surface of last_side_mesh.hpp sampled with detail n (engine/subdiv), closed by a
// flat cap meshed to the same rim samples, at exactly the asked triangle count (rounded down to even).
//
// Count: a closed triangle mesh has 2 n^2 triangles per control quad, and the box of nx x ny x nz
// control cells has 2 (nx ny + nx nz + ny nz) quads; the box is chosen near the last's proportions
// (each side within 3 cells) with the largest count not above 99 % of the target. The flat cap
// (top_cap.hpp) takes every triangle the side leaves: a grid finer than the rim's arcs, sized to its
// share, with one transition row to the rim samples.
#include "engine/core/tri_mesh.hpp"
#include "engine/lastgen/last_shape.hpp"

namespace lastcut {

// The detail n for ~ target_triangles triangles: n = 4 (the Catmull-Clark-like density) for the default
// 50k triangles, fewer for small meshes, at most 8; the control mesh has ~ target / (2 n^2) quads.
int bezier_detail_for(int target_triangles);

// The last's closed, outward surface (mm) with target_triangles (rounded down to even) triangles.
// Throws EngineError when the control mesh cannot be built (see last_side_mesh).
TriMesh bezier_last_surface(const LastShape& shape, const LastParams& params);

}  // namespace lastcut
