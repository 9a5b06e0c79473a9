// The outline filter of injective ARAP (Smith & Schaefer 2015); see outline_clearance.hpp.
#include "engine/flatten/outline_clearance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "engine/core/engine_error.hpp"
#include "engine/core/polygon.hpp"
#include "engine/core/segment_predicates.hpp"

namespace lastcut {
namespace {

// A pair of edges already closer than the clearance may narrow by at most half its gap per step: it never
// touches, and a start map whose outline has such pairs (a boundary-first start's narrow notch) is not
// frozen by them. Requiring such a pair never to narrow stalled the FIND medial half at its first step.
constexpr double kKeptShare = 0.5;

Eigen::Vector2d at(const Eigen::MatrixXd& UV, int vertex) { return UV.row(vertex).transpose(); }

}  // namespace

double segment_distance_mm(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                           const Eigen::Vector2d& d) {
  if (segments_touch(a, b, c, d)) return 0.0;
  return std::min({distance_to_segment(a, c, d), distance_to_segment(b, c, d), distance_to_segment(c, a, b),
                   distance_to_segment(d, a, b)});
}

OutlineClearance::OutlineClearance(std::vector<int> loop, double clearance_mm)
    : loop_(std::move(loop)), clearance_mm_(clearance_mm) {
  if (loop_.size() < 3) throw EngineError("flatten: the boundary loop has fewer than 3 vertices");
  if (!(clearance_mm_ >= 0.0)) throw EngineError("flatten: the outline clearance must be >= 0 mm");
}

template <typename Pair>
bool OutlineClearance::for_each_near_pair(const Eigen::MatrixXd& UV, double reach_mm, Pair pair) const {
  const int n = static_cast<int>(loop_.size());
  Eigen::Vector2d lo = at(UV, loop_[0]), hi = lo;
  double total_length = 0.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d p = at(UV, loop_[i]);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
    total_length += (at(UV, loop_[(i + 1) % n]) - p).norm();
  }
  if (!lo.allFinite() || !hi.allFinite()) return pair(-1, -1);  // a diverged map: let the caller refuse it
  lo.array() -= reach_mm;
  hi.array() += reach_mm;
  // Cells about two mean edges wide, never finer than the reach nor than 1/1024 of the extent.
  const double extent = std::max(hi.x() - lo.x(), hi.y() - lo.y());
  const double cell = std::max({2.0 * total_length / n, 2.0 * reach_mm, extent / 1024.0, 1e-9});
  const auto cell_of = [&](double value, double origin) { return static_cast<std::int64_t>((value - origin) / cell); };
  const std::int64_t rows = cell_of(hi.y(), lo.y()) + 1;

  // Per edge its cell range; (cell key, edge) sorted so that each cell's edges are consecutive.
  std::vector<std::array<std::int64_t, 4>> range(static_cast<size_t>(n));
  std::vector<std::pair<std::int64_t, int>> entries;
  entries.reserve(4 * static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d a = at(UV, loop_[i]), b = at(UV, loop_[(i + 1) % n]);
    auto& r = range[static_cast<size_t>(i)];
    r = {cell_of(std::min(a.x(), b.x()) - reach_mm, lo.x()), cell_of(std::max(a.x(), b.x()) + reach_mm, lo.x()),
         cell_of(std::min(a.y(), b.y()) - reach_mm, lo.y()), cell_of(std::max(a.y(), b.y()) + reach_mm, lo.y())};
    for (std::int64_t x = r[0]; x <= r[1]; ++x)
      for (std::int64_t y = r[2]; y <= r[3]; ++y) entries.emplace_back(x * rows + y, i);
  }
  std::sort(entries.begin(), entries.end());
  for (size_t s = 0; s < entries.size();) {
    size_t e = s;
    while (e < entries.size() && entries[e].first == entries[s].first) ++e;
    const std::int64_t x = entries[s].first / rows, y = entries[s].first % rows;
    for (size_t p = s; p < e; ++p) {
      for (size_t q = p + 1; q < e; ++q) {
        const int i = entries[p].second, j = entries[q].second;  // i < j: sorted within the cell
        if (j == i + 1 || (i == 0 && j == n - 1)) continue;      // neighbours share a vertex
        const auto& ri = range[static_cast<size_t>(i)];
        const auto& rj = range[static_cast<size_t>(j)];
        // Visit each pair once: in the lowest cell both ranges share.
        if (x != std::max(ri[0], rj[0]) || y != std::max(ri[2], rj[2])) continue;
        if (!pair(i, j)) return false;
      }
    }
    s = e;
  }
  return true;
}

bool OutlineClearance::crosses(const Eigen::MatrixXd& UV) const {
  const int n = static_cast<int>(loop_.size());
  return !for_each_near_pair(UV, 0.0, [&](int i, int j) {
    if (i < 0) return false;
    return !segments_touch(at(UV, loop_[i]), at(UV, loop_[(i + 1) % n]), at(UV, loop_[j]),
                           at(UV, loop_[(j + 1) % n]));
  });
}

bool OutlineClearance::keeps_clear(const Eigen::MatrixXd& current, const Eigen::MatrixXd& trial) const {
  const int n = static_cast<int>(loop_.size());
  return for_each_near_pair(trial, 0.5 * clearance_mm_, [&](int i, int j) {
    if (i < 0) return false;
    const int a = loop_[i], b = loop_[(i + 1) % n], c = loop_[j], d = loop_[(j + 1) % n];
    const double gap = segment_distance_mm(at(trial, a), at(trial, b), at(trial, c), at(trial, d));
    if (gap >= clearance_mm_) return true;
    // Closer than the clearance: allowed only for a pair that was already closer, by kKeptShare.
    const double before = segment_distance_mm(at(current, a), at(current, b), at(current, c), at(current, d));
    return before < clearance_mm_ && gap > 0.0 && gap >= kKeptShare * before;
  });
}

double OutlineClearance::smallest_gap_mm(const Eigen::MatrixXd& UV, int loop_separation) const {
  const int n = static_cast<int>(loop_.size());
  double smallest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (std::min(j - i, n - (j - i)) <= loop_separation) continue;
      smallest = std::min(smallest, segment_distance_mm(at(UV, loop_[i]), at(UV, loop_[(i + 1) % n]),
                                                        at(UV, loop_[j]), at(UV, loop_[(j + 1) % n])));
    }
  }
  return smallest;
}

}  // namespace lastcut
