#pragma once
// Closing scan holes so that later steps (segmentation into disks) see a watertight surface, with a
// patch that continues the surface instead of a flat lid.
//
// A hole is a loop of boundary edges (edges used by one triangle only). Its size is its size across:
// the largest distance between two of its vertices. Not its perimeter: a scanner leaves ragged edges,
// and a hole 12 mm across whose boundary zig-zags measures 72 mm around is still a 12 mm hole.
// Loops up to max_across_mm are closed; larger ones are left open (a last's top opening in some scans,
// a real defect): the caller decides what a remaining boundary means.
//
// Before patching, a ragged hole is widened to a star-shaped one (seen from its centroid in its best-fit
// plane) by removing the faces behind the edge's backward teeth; the patch replaces them too.
// The patch, after P. Liepa, "Filling Holes in Meshes", Eurographics Symposium on Geometry Processing
// 2003 (triangulate, refine to the surrounding edge length, fair), with a simpler triangulation:
//   1. rings: concentric rings between the loop and its centroid, spaced by the loop's mean edge
//      length and each with as many vertices as that spacing allows along it, joined ring to ring
//      by a zipper (each next triangle takes the nearer next vertex by arc-length fraction), the
//      innermost ring closed by a fan; the patch uses each loop edge reversed, so the faces keep
//      the surface's outward orientation;
//   2. fairing: the new vertices solve the uniform bi-Laplacian (umbrella operator applied twice,
//      Liepa section 5, Kobbelt et al. 1998) with every old vertex fixed, so the patch meets the
//      surrounding surface with its slope and bends with it, rather than spanning it flat.
#include <vector>

#include "engine/core/tri_mesh.hpp"

namespace lastcut {

// The size across of a loop of vertices (largest distance between two of them), mm.
double loop_across_mm(const Eigen::MatrixXd& V, const std::vector<int>& loop);

// mesh: V #V x 3 mm, F #F x 3, consistently oriented. Replaces the faces at the holes' ragged edges and
// appends the patches (indices change). Returns the size across (mm) of each filled hole as the scan
// had it, in the order of the mesh's boundary loops. Throws EngineError if the fairing system cannot be solved.
std::vector<double> fill_holes(TriMesh& mesh, double max_across_mm);

}  // namespace lastcut
