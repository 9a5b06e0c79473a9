#include "engine/nest/overlap_proxy.hpp"

#include <algorithm>
#include <cmath>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace lastcut::nest_detail {

double pair_overlap(const OrientedShape& a, const Point2& offset_a, const OrientedShape& b, const Point2& offset_b,
                    double eps_mm, double stop_above) {
  // Every pole pair counts, also pairs far apart: their decaying tail makes the measure fall as the
  // pieces' bulk moves apart even where the overlap itself is not covered by poles (the tips of
  // triangles and diamonds). Culling pairs beyond a few eps would leave such overlaps on a plateau
  // the search cannot descend from.
  // b's poles are taken four at a time (SSE2, part of every x86-64 CPU; a plain loop elsewhere).
  const Point2 shift = offset_a - offset_b;
  const PoleLanes& lanes = b.pole_lanes;
  const size_t count = lanes.radius.size();
  const float eps = static_cast<float>(eps_mm), eps2 = eps * eps;
  double total = eps_mm * eps_mm;  // colliding outlines overlap a little even where no poles meet
  for (const Pole& p : a.poles) {
    const float cx = static_cast<float>(p.center.x() + shift.x()), cy = static_cast<float>(p.center.y() + shift.y());
    const float r = static_cast<float>(p.radius_mm);
#if defined(__SSE2__)
    const __m128 vcx = _mm_set1_ps(cx), vcy = _mm_set1_ps(cy), vr = _mm_set1_ps(r);
    const __m128 veps = _mm_set1_ps(eps), veps2 = _mm_set1_ps(eps2), vtwo_eps = _mm_set1_ps(2 * eps);
    __m128 sum = _mm_setzero_ps();
    for (size_t k = 0; k < count; k += 4) {
      const __m128 dx = _mm_sub_ps(vcx, _mm_loadu_ps(&lanes.x[k]));
      const __m128 dy = _mm_sub_ps(vcy, _mm_loadu_ps(&lanes.y[k]));
      const __m128 rq = _mm_loadu_ps(&lanes.radius[k]);
      const __m128 distance = _mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)));
      const __m128 pd = _mm_sub_ps(_mm_add_ps(vr, rq), distance);
      // smoothed_depth: pd where pd >= eps, else eps^2 / (2 eps - pd) (2 eps - pd > eps > 0 there).
      const __m128 deep = _mm_cmpge_ps(pd, veps);
      const __m128 tail = _mm_div_ps(veps2, _mm_max_ps(_mm_sub_ps(vtwo_eps, pd), veps));
      const __m128 depth = _mm_or_ps(_mm_and_ps(deep, pd), _mm_andnot_ps(deep, tail));
      sum = _mm_add_ps(sum, _mm_mul_ps(depth, _mm_min_ps(vr, rq)));
    }
    alignas(16) float lane_sums[4];
    _mm_store_ps(lane_sums, sum);
    total += static_cast<double>(lane_sums[0]) + lane_sums[1] + lane_sums[2] + lane_sums[3];
#else
    for (size_t k = 0; k < count; ++k) {
      const float dx = cx - lanes.x[k], dy = cy - lanes.y[k];
      const float pd = r + lanes.radius[k] - std::sqrt(dx * dx + dy * dy);
      total += static_cast<double>(pd >= eps ? pd : eps2 / (2 * eps - pd)) * std::min(r, lanes.radius[k]);
    }
#endif
    if (total > stop_above) return total;
  }
  return total;
}

double rectangle_exterior_overlap(const OrientedShape& shape, const Point2& offset, const Box& inside, double eps_mm) {
  const Box world = shape.box.shifted(offset);
  if (inside.contains(world)) return 0;
  double total = 0, largest_radius = 0;
  for (const Pole& p : shape.poles) {
    const Point2 c = p.center + offset;
    const double depth_inside = std::min({c.x() - inside.x0, inside.x1 - c.x(), c.y() - inside.y0, inside.y1 - c.y()});
    total += smoothed_depth(p.radius_mm - depth_inside, eps_mm) * p.radius_mm;
    largest_radius = std::max(largest_radius, p.radius_mm);
  }
  const double protrusion = std::max(0.0, inside.x0 - world.x0) + std::max(0.0, world.x1 - inside.x1) +
                            std::max(0.0, inside.y0 - world.y0) + std::max(0.0, world.y1 - inside.y1);
  return total + protrusion * largest_radius;
}

}  // namespace lastcut::nest_detail
