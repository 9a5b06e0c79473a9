#pragma once
// 1-to-4 midpoint subdivision: every triangle is split at its edge midpoints into four, so the
// triangle count grows by exactly 4 and shapes are kept (no smoothing). Shared edges get one
// midpoint, so a closed mesh stays closed and orientation is preserved.
#include "engine/core/tri_mesh.hpp"

namespace lastcut {

// Returns the subdivided mesh: the original #V vertices first, then one per edge. #F' = 4 #F.
TriMesh subdivide_midpoint(const TriMesh& mesh);

}  // namespace lastcut
