#pragma once
// The part of a line drawn on the forme that lies on one half, and where its ends are: the 2D step of
// lifting a forme drawing (forme_lift.hpp). The forme shows both halves overlaid and they differ a
// little, so a line drawn for both halves runs a little outside one of them here and there:
//   - points up to kFormeOutsideGrace_mm outside the half are moved onto its outline, where they lie
//     between points inside it; where the line leaves the half (its ends drawn past an edge, or a line
//     for both halves that runs past one half's edge onto the other's), it is cut where it crosses the
//     outline;
//   - a run's end must lie on the half's feather line, top edge or centre line (front or back seam), or
//     on another style line of the same half, within kFormeEndReach_mm; it is moved onto it.
// Refused in one line, naming the line and giving forme coordinates: a line farther than the grace
// outside every half it is drawn for, a line end inside the upper.
#include <vector>

#include "engine/style/forme_drawing.hpp"
#include "engine/style/forme_layout.hpp"
#include "engine/style/triangle_locator.hpp"

namespace lastcut {

inline constexpr double kFormeOutsideGrace_mm = 2.0;
inline constexpr double kFormeEndReach_mm = 1.0;

// One half of the forme as the lift reads it: its triangles on the forme, searchable.
struct FormeHalfShape {
  const FormeHalfLayout* layout = nullptr;
  FlatLocator triangles;
  explicit FormeHalfShape(const FormeHalfLayout& laid);
  // 0 inside the half (within 1e-9 mm), else the distance to its outline (mm).
  double outside_mm(const Point2& forme_point) const;
  // The half's 3D point (canonical frame) under a forme point inside it (or its closest point).
  Eigen::Vector3d surface_point(const Point2& forme_point) const;
};

enum class RunEndKind { Feather, Top, FrontSeam, BackSeam, Line };

struct RunEnd {
  RunEndKind kind = RunEndKind::Feather;
  // On an outline edge: the segment [vertex, vertex + 1] of FormeEdge::vertices and the weight of its
  // second vertex, and the share of the edge's 3D length there (forme_boundary.hpp).
  std::size_t segment = 0;
  double weight = 0, share = 0;
};

struct HalfRun {
  int half = 0;                      // 0 medial, 1 lateral
  std::size_t line = 0;              // index into FormeDrawing::lines
  std::vector<Point2> points_mm;     // on the forme, inside the half or on its outline, >= 2
  bool closed = false;               // a closed line wholly on the half (first point repeated last): no ends
  RunEnd first, last;                // when open, after settle_run_ends
};

// The line sampled every `step_mm` at most (its drawn points kept).
std::vector<Point2> densified(const std::vector<Point2>& points, double step_mm);

// The runs of drawn line `line` (points: densified) on the half; none when it does not come within the
// grace of it. outside_elsewhere[i]: how far point i lies outside the other half the line is drawn for
// (infinite for a line on one half only): a point past the grace of both is refused.
std::vector<HalfRun> runs_on_half(const FormeDrawing& drawing, std::size_t line, const std::vector<Point2>& points,
                                  const FormeHalfShape& half, int half_index, const std::vector<double>& outside_elsewhere);

// Classifies each open run's two ends and moves them onto what they end on; `runs`: all runs on one
// half, of every line. Throws EngineError for an end that reaches nothing.
void settle_run_ends(const FormeDrawing& drawing, const FormeHalfShape& half, std::vector<HalfRun>& runs);

}  // namespace lastcut
