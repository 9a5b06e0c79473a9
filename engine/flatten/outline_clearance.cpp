// The outline filter of injective ARAP (Smith & Schaefer 2015); see outline_clearance.hpp.
#include "engine/flatten/outline_clearance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "engine/core/engine_error.hpp"
#include "engine/core/near_edge_pairs.hpp"
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
  const EdgePairScan scan = for_each_near_edge_pair(
      static_cast<int>(loop_.size()), [&](int k) { return at(UV, loop_[static_cast<size_t>(k)]); }, reach_mm,
      [&](int i, int j) { return pair(std::min(i, j), std::max(i, j)); });
  if (scan == EdgePairScan::NotFinite) return pair(-1, -1);  // a diverged map: let the caller refuse it
  return scan == EdgePairScan::Completed;
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
