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
// plane, no edge steeper than 15 degrees to the ray from the centroid) by removing the faces behind the
// edge's backward teeth and steep flanks, a few rounds; the patch replaces them too.
// The patch, after P. Liepa, "Filling Holes in Meshes", Eurographics Symposium on Geometry Processing
// 2003 (triangulate, refine to the surrounding edge length, fair), with a simpler triangulation:
//   1. rings, laid out flat in the loop's plane: copies of the loop shrunk towards its centroid by
//      1 - j/R (R about the loop's mean radius over its mean edge length), each keeping the directions
//      of the loop's vertices as seen from the centroid, every second one dropped where the ring's
//      edges would fall under half the loop's; ring to ring joined by angle around the centroid, the
//      innermost ring closed by a fan. Bands with the same directions are rows of trapezoids, which
//      cannot fold for a star-shaped loop; a halving band is checked in the plane and not halved
//      where it would fold. Each loop edge is used reversed, so the faces keep the surface's outward
//      orientation;
//   2. fairing: the new vertices move only along the plane's normal (the patch is a height field
//      over the plane, so it cannot fold) until the bi-Laplacian vanishes at each of them, every old
//      vertex fixed (Liepa section 5, Kobbelt et al. 1998; bilaplacian_fairing.hpp): the patch meets
//      the surrounding surface with its slope and bends with it, rather than spanning it flat.
// A loop that trimming cannot make star-shaped (30 rounds) is closed by a fan around its centroid,
// faired the same way, and reported (HoleRepair::fan).
#include <vector>

#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"

namespace lastcut {

// The size across of a loop of vertices (largest distance between two of them), mm. V #V x 3 mm.
double loop_across_mm(const Eigen::MatrixXd& V, const std::vector<int>& loop);

// One closed hole, for the job's report.
struct HoleRepair {
  double across_mm = 0;    // the hole's size across as the scan had it (before its teeth were trimmed)
  int patch_vertices = 0;  // vertices the patch added
  bool fan = false;        // the hole did not become star-shaped: closed by a fan around its centroid
                           // (faired too, but its triangles may fold where the edge is very ragged)
};

// mesh: V #V x 3 mm, F #F x 3, consistently oriented. Closes every boundary loop up to max_across_mm
// across; replaces the faces at those holes' ragged edges and appends the patches (vertex and face
// indices change). Returns one entry per closed hole, in the order of the scan's boundary loops.
// topology: mesh's (build_mesh_topology(mesh.F, mesh.V.rows())); on return the topology of the mesh
// with its holes closed, for the steps after it. It is rebuilt once per change of the faces: after
// each trimming round that removes some, and once when the patches are added.
// Throws EngineError if the fairing system cannot be solved or the topology is another mesh's.
std::vector<HoleRepair> fill_holes(TriMesh& mesh, MeshTopology& topology, double max_across_mm);

// The same, building the mesh's topology itself.
std::vector<HoleRepair> fill_holes(TriMesh& mesh, double max_across_mm);

}  // namespace lastcut
