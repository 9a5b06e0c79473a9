#pragma once
// A last triangulated the way many scanner exports and CAD meshers do it, not the way a remesher
// would: rings of vertices across the last (planes x = const, spaced densest at the ends, as a
// lofted surface's sections are), each ring the section's outline sampled at equal angles around
// its centre, consecutive rings joined by quads split into two triangles, and the heel and toe
// closed by a fan of thin triangles around a pole vertex. Triangles are long and thin across the
// instep and slivers at the poles: the input the mold quality gate and the flattening must
// survive (issue: scans as scanners make them).
#include "engine/core/tri_mesh.hpp"
#include "engine/lastgen/last_shape.hpp"

namespace lastcut {

// About target_triangles triangles (2 x rings x points per ring), closed, outward-oriented, mm,
// in the canonical frame of `shape`. Throws EngineError when a section's centre falls outside it.
TriMesh lofted_last_surface(const LastShape& shape, int target_triangles);

}  // namespace lastcut
