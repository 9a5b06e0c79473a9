#pragma once
// How much two colliding pieces overlap, measured on their poles (inscribed circles): the sum over
// pole pairs of a smoothed penetration depth times the smaller radius. Collision itself is decided
// exactly on the conservative outlines; the proxy only grades it, so it is positive whenever the
// outlines collide and steers the guided local search towards separating them (sparrow, Gardeyn,
// Vanden Berghe & Wauters, arXiv:2509.13329, 2025; penetration-depth overlap after Umetani et al. 2009).
#include <limits>

#include "engine/nest/nest_geometry.hpp"
#include "engine/nest/nest_shapes.hpp"

namespace lastcut::nest_detail {

// Penetration depth pd (mm) made positive and smooth: pd above eps_mm, a decaying tail below.
inline double smoothed_depth(double pd_mm, double eps_mm) {
  return pd_mm >= eps_mm ? pd_mm : eps_mm * eps_mm / (2 * eps_mm - pd_mm);
}

// Overlap of two colliding pieces a (at offset_a) and b (at offset_b), mm^2. Stops summing (and
// returns a value above stop_above) once the sum exceeds stop_above.
double pair_overlap(const OrientedShape& a, const Point2& offset_a, const OrientedShape& b, const Point2& offset_b,
                    double eps_mm, double stop_above = std::numeric_limits<double>::infinity());

// Overlap of a piece with the outside of the rectangle `inside` (0 when it is within), mm^2.
double rectangle_exterior_overlap(const OrientedShape& shape, const Point2& offset, const Box& inside, double eps_mm);

}  // namespace lastcut::nest_detail
