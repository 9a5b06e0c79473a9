#pragma once
// Where a scanner merged two overlapping passes: a stitching seam. Handheld and multi-view
// scanners register each pass to the others and zipper them together where they overlap; the
// registration is never exact, so the merged surface has a step of a tenth of a millimetre or so
// along the seam, and zippering cuts the triangles there into thin ones (G. Turk and M. Levoy,
// "Zippered polygon meshes from range images", SIGGRAPH 1994, describe the merge).
// This models both: a plane through the last is the seam; every edge crossing it is split at the
// crossing (engine/segment/level_set_cut.hpp, without snapping), so the triangles it cuts become
// thin ones wherever it passes near a vertex; and the
// second pass (the plane's positive side) is misregistered by a small rigid motion, the seam's own
// vertices by half of it, so the surface stays one closed sheet with a step at the seam.
#include <random>

#include "engine/core/tri_mesh.hpp"

namespace lastcut {

// mesh: a closed or open triangle mesh, mm, counter-clockwise faces (kept so). Adds `count` seams,
// each a plane through a random point in the middle half of the mesh's box with a random normal.
// The second pass is shifted by misregistration_mm / 2 and turned by misregistration_mm / 200 rad
// about the seam point, both in random directions: a step of up to about misregistration_mm along
// the seam. All draws come from `random`.
void add_stitching_seams(TriMesh& mesh, int count, double misregistration_mm, std::mt19937_64& random);

}  // namespace lastcut
