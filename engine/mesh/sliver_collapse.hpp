#pragma once
// Slivers taken out of a scan before it is denoised and flattened, only where the scan has them.
// Scanner exports and CAD meshers close a lofted surface with fans of triangles around a pole,
// a hundredth of a millimetre across; a scanner's point error (0.05-0.3 mm) is far larger than
// such a triangle, so noise folds the fan over itself and ARAP cannot untangle what is folded in
// 3D. Edges much shorter than the scan's median edge are collapsed to their midpoints (Hoppe et
// al., "Mesh optimization", SIGGRAPH 1993, edge collapse; the link condition of Dey et al. keeps
// the mesh a manifold: OpenMesh's is_collapse_ok). Unlike the remesher's collapse
// (isotropic_remesh.cpp) a collapse that turns a neighbouring triangle over is not refused: in a
// folded fan there is no orientation worth keeping; the bilateral denoising that follows
// (scan_denoise.hpp) smooths what the collapse leaves. Boundary vertices stay (hole rims).
#include "engine/core/tri_mesh.hpp"

namespace lastcut {

struct SliverReport {
  int short_edges = 0;  // sliver half-edges found in the scan
  int collapsed = 0;    // edges collapsed (0: the scan was left as it was)
  double limit_mm = 0;  // fraction x median edge
};

// Collapses sliver edges: shorter than `fraction` x the median edge length and than a fifth of
// another edge of one of their triangles (a needle's short side), when more than `min_share` of
// all half-edges are such (a few are no reason to touch a scan). mesh: a 2-manifold,
// mm; vertex and face order change when anything is collapsed.
SliverReport collapse_slivers(TriMesh& mesh, double fraction = 0.2, double min_share = 0.001);

}  // namespace lastcut
