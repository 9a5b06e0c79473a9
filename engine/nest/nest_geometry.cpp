#include "engine/nest/nest_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace lastcut::nest_detail {
namespace {

void simplify_span(const std::vector<Point2>& ring, size_t first, size_t last, double tolerance,
                   std::vector<char>& keep) {
  const size_t n = ring.size();
  double worst = -1;
  size_t worst_index = first;
  for (size_t i = (first + 1) % n; i != last; i = (i + 1) % n) {
    const double d = distance_to_segment(ring[i], ring[first], ring[last]);
    if (d > worst) worst = d, worst_index = i;
  }
  if (worst > tolerance) {
    keep[worst_index] = 1;
    simplify_span(ring, first, worst_index, tolerance, keep);
    simplify_span(ring, worst_index, last, tolerance, keep);
  }
}

}  // namespace

Box bounding_box(const std::vector<Point2>& points) {
  Box box{points[0].x(), points[0].y(), points[0].x(), points[0].y()};
  for (const Point2& p : points) {
    box.x0 = std::min(box.x0, p.x());
    box.y0 = std::min(box.y0, p.y());
    box.x1 = std::max(box.x1, p.x());
    box.y1 = std::max(box.y1, p.y());
  }
  return box;
}

bool rings_collide(const PlacedRing& a, const PlacedRing& b) {
  const Box wa = a.world_box(), wb = b.world_box();
  if (!wa.overlaps(wb)) return false;
  // Only edges that reach into the common box can cross; test those pairs, a in b's frame.
  // Padded: the box and the shifted edges are rounded differently, and an edge that spans the common
  // box exactly must not be culled by a last-bit difference.
  const double pad = 1e-9 * (std::abs(wa.x0) + std::abs(wa.y0) + wa.width() + wa.height() + 1.0);
  const Box common{std::max(wa.x0, wb.x0) - pad, std::max(wa.y0, wb.y0) - pad, std::min(wa.x1, wb.x1) + pad,
                   std::min(wa.y1, wb.y1) + pad};
  const Point2 shift = a.offset - b.offset;
  const Box common_b = common.shifted(-b.offset);
  const auto& ra = *a.ring;
  const auto& rb = *b.ring;
  auto outside_common = [&common_b](const Point2& p, const Point2& q) {
    return std::max(p.x(), q.x()) < common_b.x0 || std::min(p.x(), q.x()) > common_b.x1 ||
           std::max(p.y(), q.y()) < common_b.y0 || std::min(p.y(), q.y()) > common_b.y1;
  };
  // b's edges in the common box, listed once (a fixed buffer: no allocation in this hot path; rings
  // longer than it keep every edge).
  constexpr size_t kListed = 256;
  std::array<std::uint16_t, kListed> listed;
  size_t listed_count = 0;
  const size_t m = rb.size();
  const bool list_b = m <= kListed;
  if (list_b) {
    for (size_t j = 0; j < m; ++j)
      if (!outside_common(rb[j], rb[(j + 1) % m])) listed[listed_count++] = static_cast<std::uint16_t>(j);
  }
  const size_t candidates = list_b ? listed_count : m;
  for (size_t i = 0, n = candidates == 0 ? 0 : ra.size(); i < n; ++i) {
    const Point2 p = ra[i] + shift, q = ra[(i + 1) % n] + shift;
    if (outside_common(p, q)) continue;
    const double px0 = std::min(p.x(), q.x()), px1 = std::max(p.x(), q.x());
    const double py0 = std::min(p.y(), q.y()), py1 = std::max(p.y(), q.y());
    for (size_t k = 0; k < candidates; ++k) {
      const size_t j = list_b ? listed[k] : k;
      const Point2& c = rb[j];
      const Point2& d = rb[(j + 1) % m];
      if (std::max(c.x(), d.x()) < px0 || std::min(c.x(), d.x()) > px1 || std::max(c.y(), d.y()) < py0 ||
          std::min(c.y(), d.y()) > py1)
        continue;
      if (segments_touch(p, q, c, d)) return true;
    }
  }
  // No boundary contact: collide only when one contains the other.
  if (point_in_ring(a.interior_point() + shift, rb)) return true;
  return point_in_ring(b.interior_point() - shift, ra);
}

std::vector<Point2> simplify_ring(const std::vector<Point2>& ring, double tolerance_mm) {
  const size_t n = ring.size();
  if (n <= 4 || tolerance_mm <= 0) return ring;
  size_t a = 0, b = 0;
  double far = -1;
  for (size_t i = 0; i < n; ++i) {  // the point farthest from point 0, then farthest from that
    const double d = (ring[i] - ring[0]).squaredNorm();
    if (d > far) far = d, a = i;
  }
  far = -1;
  for (size_t i = 0; i < n; ++i) {
    const double d = (ring[i] - ring[a]).squaredNorm();
    if (d > far) far = d, b = i;
  }
  std::vector<char> keep(n, 0);
  keep[a] = keep[b] = 1;
  simplify_span(ring, a, b, tolerance_mm, keep);
  simplify_span(ring, b, a, tolerance_mm, keep);
  std::vector<Point2> result;
  for (size_t i = 0; i < n; ++i)
    if (keep[i]) result.push_back(ring[i]);
  return result;
}

}  // namespace lastcut::nest_detail
