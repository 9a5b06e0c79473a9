#pragma once
// Per-edge allowances of a half-last mold. The net outline (the last's edge: where the leather
// bends under the insole, is stitched to the other half, or is finished at the top) is split at
// the landmark vertices into four edges:
//   feather line   toe -> heel along the bottom       lasting margin, folded under the insole
//   front seam     top_front -> toe (centre cut)      seam allowance, stitched to the other half
//   back seam      heel -> top_back (centre cut)      seam allowance
//   top line       top_back -> top_front              finished edge, usually no allowance
// Each edge is grown by its own distance as an open path with round ends (Clipper 6.4 by
// Angus Johnson, ClipperOffset etOpenRound) and the bands are united with the net shape. Where two
// different allowances meet, the larger band's round end leaves a concave corner against the
// smaller one; a morphological closing (offset out, then in, by the larger allowance; Serra 1982,
// "Image Analysis and Mathematical Morphology", Academic Press) applied only near that landmark
// replaces the corner by a tangent fillet, so the knife meets no corner at a transition.
#include <string>
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

// Allowances in mm (>= 0) per edge kind. Shop values are in docs/mold-allowances.md.
struct EdgeAllowances {
  double lasting_mm = 0.0;  // feather line
  double seam_mm = 0.0;     // front and back centre cut
  double top_mm = 0.0;      // top line
};

enum class EdgeKind { Feather, FrontSeam, BackSeam, Top };

std::string to_string(EdgeKind kind);
double allowance_of(const EdgeAllowances& allowances, EdgeKind kind);

// One edge of the net outline: the open polyline between two landmarks, in outline (CCW) order.
struct NetEdge {
  EdgeKind kind = EdgeKind::Feather;
  std::string from, to;         // landmark names at points.front() and points.back()
  std::vector<Point2> points;   // mm, >= 2 points
};

// The landmark names that bound the four edges.
inline constexpr const char* kEdgeLandmarks[] = {"toe", "heel", "top_back", "top_front"};

// net: CCW simple outline (mm); landmark_index: the outline index of "toe", "heel", "top_back",
// "top_front" (all four). Returns the four edges in outline order starting at the first landmark.
// Throws EngineError when two landmarks share a vertex or they do not run in the order
// toe, heel, top_back, top_front around the outline (either direction).
std::vector<NetEdge> split_net_edges(const Polygon2& net, const std::vector<std::pair<std::string, int>>& landmark_index);

// One stretch of a net outline and how far the cut line lies outside it (mm, >= 0).
struct AllowanceEdge {
  std::vector<Point2> points;  // mm, >= 2 points, in outline order; consecutive edges share their end points
  double allowance_mm = 0.0;
};

// The cut outline (CCW, simple, mm) of net grown edge by edge: every point of an edge's band lies
// allowance_mm from it; where two different allowances meet, the corner is filled (see above).
// tolerance_mm: chord error of the round parts (> 0). Throws EngineError for a negative or infinite
// allowance.
Polygon2 grow_by_allowances(const Polygon2& net, const std::vector<AllowanceEdge>& edges, double tolerance_mm);

// The cut outline (CCW, simple, mm) of net grown per edge: every point of edge e's band boundary
// lies allowance_of(e) from e. tolerance_mm: chord error of the round parts (> 0).
// Throws EngineError when an allowance is negative or not finite.
Polygon2 grow_by_edge_allowances(const Polygon2& net, const std::vector<NetEdge>& edges,
                                 const EdgeAllowances& allowances, double tolerance_mm);

}  // namespace lastcut
