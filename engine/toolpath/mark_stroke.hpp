#pragma once
// The path the mark tool takes for one mark of a placed piece: a slit, or a V where the machine
// profile asks for V notches ([notch] shape = "v", docs/cut-files.md).
//
// Which marks are notches. A mark named "toe", "heel", "top_front" or "top_back" is a landmark:
// one of the four points engine/segment finds on a half of the last, which make_mold marks on a
// mold and mold DXFs carry by name. Every other mark is a notch: what a pattern room puts on a piece
// to match it to its neighbour when closing the upper (pattern pieces' marks are named "notch",
// a mold's balance notches "balance_seam_front_3", a style piece's notches after their line,
// "vamp 2" or "vamp x front seam"). Notches take the profile's shape; a landmark always keeps its
// slit, because it marks a point of the last the laster centres the piece on (and the toe region
// is measured from), not a notch to be matched, and its one line points at that point.
#include <string>
#include <vector>

#include "engine/core/polygon.hpp"
#include "engine/toolpath/machine_profile.hpp"
#include "engine/toolpath/placed_piece.hpp"

namespace lastcut {

// True for the four landmark names above (exact, case-sensitive, as lastcut writes them).
bool is_landmark_mark(const std::string& name);

// The tip path of `mark`, table coordinates (mm): {from, to} for a slit; for a V notch
// {from - w/2 n, to, from + w/2 n}, w the profile's v_width_mm and n the unit vector across the
// mark (from -> to turned by +90 deg), so the V opens at the outline and closes at the inner end.
// Empty when the mark is shorter than 1e-6 mm: there is nothing to cut.
std::vector<Point2> mark_stroke(const PlacedMark& mark, const NotchOptions& notch);

}  // namespace lastcut
