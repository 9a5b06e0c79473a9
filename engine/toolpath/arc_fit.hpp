#pragma once
// Arc fitting for G-code: a polyline is replaced, greedily from its start, by circular arcs
// wherever a run of at least min_points consecutive points (and the chords between them) stays
// within tolerance_mm of the circle through the run's first, middle and last point, turning one
// way and sweeping less than a full turn. Everything else stays a line. Fewer, longer moves let a
// grbl planner keep speed on curved leather edges instead of stuttering through short chords.
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

struct PathSegment {
  bool is_arc = false;
  Point2 end_mm = Point2::Zero();
  Point2 center_mm = Point2::Zero();  // arcs only
  bool counter_clockwise = false;     // arcs only: G3 when true, G2 when false
};

struct ArcFitOptions {
  double tolerance_mm = 0.01;
  int min_points = 4;             // points in a run (start included) before an arc replaces it
  double max_radius_mm = 5000.0;  // flatter runs stay lines (grbl is imprecise on huge radii)
};

// points_mm #P (>= 1): the path; returns segments from points_mm[0] to points_mm.back().
std::vector<PathSegment> fit_arcs(const std::vector<Point2>& points_mm, const ArcFitOptions& options);

}  // namespace lastcut
