#pragma once
// Edges far shorter than anything a knife or a flattening can use, collapsed out of a mesh cut from a
// surface (a style's piece, engine/style/piece_surface.hpp). Where a cut line passes a few micrometres
// from a vertex of the last, clipping leaves triangles micrometres across, edges of 0.004 mm beside
// edges of 1 mm. Their cotangent weights are huge and the least push flips them: holding a piece's sewn
// edges at their 3D length (engine/flatten/arap_held_lengths.hpp) turned one over in the derby's vamp.
// Edge collapse (Hoppe et al., "Mesh optimization", SIGGRAPH 1993) with the link condition of Dey et al.
// (OpenMesh's is_collapse_ok) keeps the mesh a manifold disk. Unlike the scan's sliver collapse
// (sliver_collapse.hpp) the outline takes part, since that is where the cut leaves its crumbs, and
// nothing is moved off it:
//   - an interior vertex is merged into a vertex on the outline, two interior ones at their midpoint;
//   - on an outline edge the vertex farther from the chord of its outline neighbours (a corner where a
//     line meets the feather line, say) stays where it is, the other goes into it;
//   - an edge between two outline vertices that is not on the outline would pinch the disk: never;
//   - a collapse that would turn a surviving triangle over (its normal reversed) is not made.
#include "engine/core/tri_mesh.hpp"

namespace lastcut {

// mesh: a 2-manifold with or without outline, mm. Collapses edges shorter than min_edge_mm; returns how
// many. Vertex and face order change when anything is collapsed.
int collapse_short_edges(TriMesh& mesh, double min_edge_mm);

}  // namespace lastcut
