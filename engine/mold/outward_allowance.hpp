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
#include <vector>

#include "engine/core/polygon.hpp"
#include "engine/mold/edge_allowance.hpp"

namespace lastcut {

// net: counter-clockwise, simple (mm); edges: its stretches in outline order, consecutive ones sharing
// their end points, together covering it once. tolerance_mm: chord error of the sectors' arcs (> 0).
// Returns the cut outline, counter-clockwise. Throws EngineError for a negative or infinite allowance.
Polygon2 grow_outward_by_allowances(const Polygon2& net, const std::vector<AllowanceEdge>& edges, double tolerance_mm);

}  // namespace lastcut
