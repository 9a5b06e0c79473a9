#pragma once
// The rigid motion of a reference pattern that covers a mold best: the motion (rotation +
// translation, optionally after a mirror) maximising the area C of the intersection of the moved
// reference with the mold. It defines the thesis's overlap measure 2C/(A+B), A = reference area,
// B = mold area (M. Sabaliauskas, doctoral thesis, Vilnius University 2017, section 4.1: computed
// molds against the wax-foil molds of production; there by counting pixels, here exactly).
//   Areas: exact polygon intersection by Clipper (Angus Johnson, Clipper 6.4, Vatti's clipping
//   algorithm: B. R. Vatti, "A generic solution to polygon clipping", CACM 35(7), 1992) on
//   integers of 1e-5 mm.
//   Starts: area centroids matched; the reference's principal axis turned onto the mold's
//   principal or secondary axis, each both ways (4 starts), unmirrored and mirrored.
//   Refinement: compass (pattern) search (Kolda, Lewis & Torczon, "Optimization by direct search:
//   new perspectives on some classical and modern methods", SIAM Review 45(3), 2003) on the angle
//   (scaled by the reference's radius of gyration to mm) and the translation, 10 directions,
//   halving the step: every start from 4 mm to 0.05 mm on outlines thinned to about 200 points,
//   then the starts within 1 % of the best on the full outlines from 0.5 mm down to 1e-5 mm (and
//   below 1e-6 rad); the best end wins.
// Mirroring is allowed by default because a pattern is the same piece for both feet: a shop keeps
// one pattern per size and draws it reversed for the other foot, so a left pattern checks a right
// mold. It is reported, and can be switched off.
#include "engine/core/polygon.hpp"

namespace lastcut {

// q = R(rotation) * S * p + translation, S = diag(-1, 1) when mirrored (x negated first).
struct PlaneMotion {
  bool mirrored = false;
  double rotation_rad = 0.0;
  Point2 translation_mm = Point2::Zero();
  Point2 apply(const Point2& p) const;
};

// The polygon moved; a mirrored polygon is reversed so that it stays counter-clockwise.
Polygon2 moved(const Polygon2& polygon, const PlaneMotion& motion);

struct OverlapOptions {
  bool allow_mirror = true;
  double final_step_mm = 1e-5;
  double final_step_rad = 1e-6;
};

struct OverlapAlignment {
  PlaneMotion motion;                 // of the reference onto the mold
  double reference_area_mm2 = 0.0;    // A
  double mold_area_mm2 = 0.0;         // B
  double intersection_area_mm2 = 0.0; // C, at `motion`
  double overlap_fraction() const { return 2.0 * intersection_area_mm2 / (reference_area_mm2 + mold_area_mm2); }
  int area_evaluations = 0;
};

// reference, mold: simple closed polygons (mm, #P >= 3). Throws EngineError when either has no area.
OverlapAlignment align_for_overlap(const Polygon2& reference, const Polygon2& mold, const OverlapOptions& options = {});

// Exact area (mm^2) of the intersection of two simple polygons (either orientation).
double intersection_area_mm2(const Polygon2& a, const Polygon2& b);

}  // namespace lastcut
