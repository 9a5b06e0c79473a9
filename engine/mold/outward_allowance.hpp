#pragma once
// A pattern piece's cut outline grown outward from its net outline by a per-edge allowance, on the
// outside only: each segment of the net sweeps a strip along its outward normal as wide as its edge's
// allowance, and each vertex a sector between its two segments' normals whose radius goes from the
// one allowance to the other. The union of the net, the strips and the sectors is the cut outline (the
// Minkowski-style offset of a polyline, built with Clipper 6.4 by Angus Johnson).
//
// Why not edge_allowance.hpp's two-sided bands: a band reaches the allowance on both sides of its edge,
// so where a piece is narrower than its widest allowance (a counter's wing tapering to the feather line,
// 18 mm of lasting margin) it crosses the opposite edge and cuts the piece bigger there; and its fillet
// at a change of allowance runs far along a narrow wedge. Growing outward only keeps every edge exactly
// where it is when its own allowance is 0, and passes from one allowance to the next round the corner.
//
// Where the allowance changes from a larger R to a smaller r > 0 (lasting to underlay), the cut line
// keeps R round the corner and comes down to r on the smaller edge at 45 degrees, over R - r mm of it:
// a chamfer that follows the corner along the outline. Turning from R to r round the corner alone
// depends on how far the outline turns there: where a style line meets the feather line at a shallow
// angle it turns a few degrees, so the cut line dropped almost square by R - r, and two meshes of one
// last that put that corner a millimetre apart along the outline gave steps 4.5 mm apart (docs/pieces.md,
// identity). The smaller side gets the leather rather than the larger: an underlay lies under its
// neighbour, and the lasting margin stays whole up to the corner. A change to 0 (a butted or raw edge)
// keeps that edge exactly in place, and its line runs on straight through its neighbour's allowance, as
// a pattern maker extends a raw edge: R ends square at the corner, and where the outline turns more
// than a right angle it is rounded at R from there to the raw edge's line, which the cut line then
// follows back to the corner. It used to turn
// from R to 0 round the corner, which bulged past the raw edge's line: on a tongue whose raw sides meet
// its 30 mm top, two round lobes wider than the tongue.
#include <vector>

#include "engine/core/polygon.hpp"
#include "engine/mold/edge_allowance.hpp"

namespace lastcut {

// net: counter-clockwise, simple (mm); edges: its stretches in outline order, consecutive ones sharing
// their end points, together covering it once. tolerance_mm: chord error of the sectors' arcs (> 0).
// Returns the cut outline, counter-clockwise. Throws EngineError for a negative or infinite allowance.
Polygon2 grow_outward_by_allowances(const Polygon2& net, const std::vector<AllowanceEdge>& edges, double tolerance_mm);

}  // namespace lastcut
