#pragma once
// The broad phase of every test of a closed ring against itself: the mold outline's simplicity, a hide
// file's rings, a reference pattern, and the outline filter of injective ARAP (which also asks for a
// clearance). It lists the pairs of edges that share no vertex and whose bounding boxes, grown by reach_mm,
// meet; the caller decides what a pair means (segments_touch, a distance).
//
// How: a uniform grid. Each edge is entered in every cell of its grown box, the entries are sorted by
// cell and, within a cell, by the boxes' low x, so a cell's pairs are scanned as a sweep over x; a pair is
// reported once, in the lowest cell both boxes share. Cells are about two mean edge lengths wide, never
// finer than twice the reach nor than 1/1024 of the ring's extent, and coarsened until the entries number at most 16 n + 2^20.
// The cost is thus near n log n on outlines, and memory stays bounded on any ring: a closing edge across
// a 2 m drawing of 20,000 points once cost 661 MB in the grid this replaces (check_pattern_outline).
// Edge i runs from point i to point i + 1 (the last back to point 0).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

enum class EdgePairScan {
  Completed,  // every near pair was visited
  Stopped,    // visit returned false
  NotFinite,  // a point is NaN or infinite: nothing was visited (no usable ring)
};

// point_at(k) -> Point2 for k in [0, n); visit(i, j) with i != j, called once per pair, returns false to stop.
template <typename PointAt, typename Visit>
EdgePairScan for_each_near_edge_pair(int n, PointAt point_at, double reach_mm, Visit visit) {
  if (n < 4) return EdgePairScan::Completed;  // in a triangle every two edges share a vertex
  std::vector<Point2> p(static_cast<size_t>(n));
  double total_length = 0.0;
  for (int k = 0; k < n; ++k) p[static_cast<size_t>(k)] = point_at(k);
  Point2 lo = p[0], hi = p[0];
  for (int k = 0; k < n; ++k) {
    const Point2& a = p[static_cast<size_t>(k)];
    if (!a.allFinite()) return EdgePairScan::NotFinite;
    lo = lo.cwiseMin(a);
    hi = hi.cwiseMax(a);
    total_length += (p[static_cast<size_t>((k + 1) % n)] - a).norm();
  }
  struct Box {
    double x0, x1, y0, y1;
  };
  std::vector<Box> box(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    const Point2& a = p[static_cast<size_t>(k)];
    const Point2& b = p[static_cast<size_t>((k + 1) % n)];
    box[static_cast<size_t>(k)] = {std::min(a.x(), b.x()) - reach_mm, std::max(a.x(), b.x()) + reach_mm,
                                   std::min(a.y(), b.y()) - reach_mm, std::max(a.y(), b.y()) + reach_mm};
  }
  const double origin_x = lo.x() - reach_mm, origin_y = lo.y() - reach_mm;
  const double extent = std::max(hi.x() - lo.x(), hi.y() - lo.y()) + 2.0 * reach_mm;
  double cell = std::max({2.0 * total_length / n, 2.0 * reach_mm, extent / 1024.0, 1e-9});
  const auto cell_of = [&](double value, double origin) { return static_cast<std::int64_t>((value - origin) / cell); };
  const auto entry_count = [&] {
    std::int64_t count = 0;
    for (const Box& b : box)
      count += (cell_of(b.x1, origin_x) - cell_of(b.x0, origin_x) + 1) * (cell_of(b.y1, origin_y) - cell_of(b.y0, origin_y) + 1);
    return count;
  };
  const std::int64_t most_entries = 16 * static_cast<std::int64_t>(n) + (std::int64_t{1} << 20);
  while (entry_count() > most_entries) cell *= 2.0;
  const std::int64_t rows = cell_of(hi.y() + reach_mm, origin_y) + 1;

  struct Entry {
    std::int64_t cell;
    double low_x;
    int edge;
  };
  std::vector<Entry> entries;
  entries.reserve(4 * static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    const Box& b = box[static_cast<size_t>(k)];
    for (std::int64_t x = cell_of(b.x0, origin_x); x <= cell_of(b.x1, origin_x); ++x)
      for (std::int64_t y = cell_of(b.y0, origin_y); y <= cell_of(b.y1, origin_y); ++y)
        entries.push_back({x * rows + y, b.x0, k});
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.cell != b.cell ? a.cell < b.cell : (a.low_x != b.low_x ? a.low_x < b.low_x : a.edge < b.edge);
  });
  for (size_t first = 0; first < entries.size();) {
    size_t end = first;
    while (end < entries.size() && entries[end].cell == entries[first].cell) ++end;
    const std::int64_t x = entries[first].cell / rows, y = entries[first].cell % rows;
    for (size_t s = first; s < end; ++s) {
      const int i = entries[s].edge;
      const Box& bi = box[static_cast<size_t>(i)];
      for (size_t t = s + 1; t < end && entries[t].low_x <= bi.x1; ++t) {
        const int j = entries[t].edge;
        const int gap = std::abs(i - j);
        if (gap == 1 || gap == n - 1) continue;  // neighbours share a vertex
        const Box& bj = box[static_cast<size_t>(j)];
        if (bj.y0 > bi.y1 || bi.y0 > bj.y1) continue;
        // Once: in the lowest cell both boxes share.
        if (x != std::max(cell_of(bi.x0, origin_x), cell_of(bj.x0, origin_x)) ||
            y != std::max(cell_of(bi.y0, origin_y), cell_of(bj.y0, origin_y)))
          continue;
        if (!visit(i, j)) return EdgePairScan::Stopped;
      }
    }
    first = end;
  }
  return EdgePairScan::Completed;
}

}  // namespace lastcut
