#pragma once
// Closing small scan holes so that later steps (segmentation into disks) see a watertight surface.
// A hole is a loop of boundary edges (edges used by one triangle only). A loop whose diameter
// (largest distance between two of its vertices) is at most max_diameter_mm is closed by a fan of
// triangles around one new vertex at the loop's centroid: simple, never creates zero-area triangles
// for the star-shaped holes a scanner leaves, and keeps the faces' outward orientation.
// Larger loops are left open (a last's top opening in some scans, a real defect): the caller
// decides what a remaining boundary means.
#include "engine/core/tri_mesh.hpp"

namespace lastcut {

// mesh: V #V x 3 mm, F #F x 3, consistently oriented. Appends one vertex and k triangles per
// filled hole of k boundary edges (three-edge holes get one triangle and no new vertex).
// Returns how many holes were filled.
int fill_holes(TriMesh& mesh, double max_diameter_mm);

}  // namespace lastcut
