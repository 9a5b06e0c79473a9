#pragma once
// Blade-offset compensation for drag knives. A drag knife's tip trails the holder axis by the
// blade offset d, like a caster, so the holder must move ahead of the wanted cut: along a straight
// edge with unit direction u it runs on the edge shifted by d*u; at a corner turning by more than
// the threshold it swings around the corner point on a circle of radius d from the old direction
// to the new one (the "corner loop"), so the tip pivots on the corner and the corner stays sharp.
// Below the threshold the holder goes straight to the next shifted edge (the error is about
// d*(1 - cos turn), negligible for small turns).
// The construction is elementary geometry (shifted edges joined by pivot arcs); no paper is followed.
#include <optional>
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

struct DragKnifeOptions {
  double blade_offset_mm = 0.25;
  double corner_threshold_deg = 30.0;  // turns above get a swivel arc
  double arc_step_deg = 10.0;          // angular step of the swivel arcs
};

// tip_path_mm #P (>= 2) the path the blade tip must cut; incoming_direction: the direction the
// blade points when the stroke starts (for a closed contour, its last edge), or nullopt when
// unknown (then the holder starts straight on the first edge).
// Returns the holder-axis path (mm). With blade_offset_mm == 0 returns the tip path.
std::vector<Point2> compensate_drag_knife(const std::vector<Point2>& tip_path_mm,
                                          const std::optional<Point2>& incoming_direction,
                                          const DragKnifeOptions& options);

// The inverse, for checking: where a blade trailing the holder by blade_offset_mm goes when the
// holder follows holder_path_mm, starting with the tip at tip_start_mm. The holder path is walked
// in steps of at most step_mm. Returns the tip positions after every step (mm).
std::vector<Point2> simulate_drag_knife_tip(const std::vector<Point2>& holder_path_mm, const Point2& tip_start_mm,
                                            double blade_offset_mm, double step_mm);

}  // namespace lastcut
