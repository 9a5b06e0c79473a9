// The boundary barrier of bijective ARAP (Smith & Schaefer 2015); see boundary_barrier.hpp.
#include "engine/flatten/boundary_barrier.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "engine/core/engine_error.hpp"
#include "engine/core/near_edge_pairs.hpp"

namespace lastcut {

BoundaryBarrier::BoundaryBarrier(std::vector<int> loop, const std::vector<double>& arc_mm,
                                 const BoundaryBarrierOptions& options)
    : loop_(std::move(loop)),
      epsilon_mm_(options.activation_mm),
      least_epsilon_mm_(options.least_activation_mm),
      stiffness_(options.stiffness) {
  if (loop_.size() < 3) throw EngineError("flatten: the boundary loop has fewer than 3 vertices");
  if (arc_mm.size() != loop_.size()) throw EngineError("flatten: one 3D length per outline edge expected");
  if (!(least_epsilon_mm_ > 0.0) || !(epsilon_mm_ >= least_epsilon_mm_) || !(stiffness_ > 0.0))
    throw EngineError("flatten: the boundary barrier needs a positive reach and stiffness");
  arc_start_mm_.resize(loop_.size());
  for (size_t k = 0; k < loop_.size(); ++k) {
    arc_start_mm_[k] = loop_length_mm_;
    loop_length_mm_ += arc_mm[k];
  }
}

// visit(k, e, t, d, reach): outline vertex k against outline edge e (from k = e to e + 1), t the closest
// point's parameter on the edge, d the distance, reach the pair's epsilon (d < reach).
template <typename Visit>
void BoundaryBarrier::for_each_active_pair(const Eigen::MatrixXd& UV, Visit visit) const {
  const int n = static_cast<int>(loop_.size());
  const auto point = [&](int k) -> Eigen::Vector2d { return UV.row(loop_[static_cast<size_t>(k)]).transpose(); };
  // Arc distance along the closed outline from vertex k to the nearer end of edge e.
  const auto arc_apart = [&](int k, int e) {
    const auto along = [&](int a, int b) {
      const double d = std::abs(arc_start_mm_[static_cast<size_t>(a)] - arc_start_mm_[static_cast<size_t>(b)]);
      return std::min(d, loop_length_mm_ - d);
    };
    return std::min(along(k, e), along(k, (e + 1) % n));
  };
  const auto try_pair = [&](int k, int e) {
    if (k == e || k == (e + 1) % n) return;  // the edge's own end
    const double reach_mm = std::min(epsilon_mm_, std::max(least_epsilon_mm_, 0.5 * arc_apart(k, e)));
    const Eigen::Vector2d p = point(k), a = point(e), b = point((e + 1) % n);
    const Eigen::Vector2d ab = b - a;
    const double length_squared = ab.squaredNorm();
    const double t = length_squared > 0.0 ? std::clamp((p - a).dot(ab) / length_squared, 0.0, 1.0) : 0.0;
    const double d = (p - a - t * ab).norm();
    if (d < reach_mm) visit(k, e, t, d, reach_mm);
  };
  // Each vertex is the start of one edge: for a near pair of edges (i, j), vertex i against edge j and
  // vertex j against edge i cover every vertex-edge pair closer than epsilon (boxes grown by epsilon / 2)
  // except a vertex against the edge after its own next one: the broad phase skips edges that share a
  // vertex, as the outline filter does. That angle closing is the fold barrier's and the guard's business.
  for_each_near_edge_pair(n, [&](int k) { return Point2(point(k)); }, 0.5 * epsilon_mm_, [&](int i, int j) {
    try_pair(i, j);
    try_pair(j, i);
    return true;
  });
}

double BoundaryBarrier::energy(const Eigen::MatrixXd& UV, std::vector<double>* gradient) const {
  const int n = static_cast<int>(loop_.size());
  double total = 0.0;
  for_each_active_pair(UV, [&](int k, int e, double t, double d, double reach_mm) {
    if (d <= 0.0) {
      total = std::numeric_limits<double>::infinity();
      return;
    }
    const BarrierValue f = barrier_at(stiffness_ * reach_mm * reach_mm, reach_mm, d);
    total += f.value;
    if (gradient == nullptr) return;
    // dE/dd, and d(d)/d(position): n for the vertex, -(1 - t) n and -t n for the edge's ends.
    const double slope = f.slope;
    const int v = loop_[static_cast<size_t>(k)], a = loop_[static_cast<size_t>(e)],
              b = loop_[static_cast<size_t>((e + 1) % n)];
    const Eigen::Vector2d closest =
        (1.0 - t) * UV.row(a).transpose() + t * UV.row(b).transpose();
    const Eigen::Vector2d normal = (UV.row(v).transpose() - closest) / d;
    std::vector<double>& g = *gradient;
    for (int c = 0; c < 2; ++c) {
      g[2 * static_cast<size_t>(v) + c] += slope * normal[c];
      g[2 * static_cast<size_t>(a) + c] -= slope * (1.0 - t) * normal[c];
      g[2 * static_cast<size_t>(b) + c] -= slope * t * normal[c];
    }
  });
  return total;
}

void BoundaryBarrier::add_curvatures(const Eigen::MatrixXd& UV, std::vector<BarrierCurvature>& terms) const {
  const int n = static_cast<int>(loop_.size());
  for_each_active_pair(UV, [&](int k, int e, double t, double d, double reach_mm) {
    if (d <= 0.0) return;
    terms.push_back({{loop_[static_cast<size_t>(k)], loop_[static_cast<size_t>(e)], loop_[static_cast<size_t>((e + 1) % n)]},
                     {1.0, -(1.0 - t), -t},
                     barrier_at(stiffness_ * reach_mm * reach_mm, reach_mm, d).curvature});
  });
}

int BoundaryBarrier::active_pairs(const Eigen::MatrixXd& UV) const {
  int count = 0;
  for_each_active_pair(UV, [&](int, int, double, double, double) { ++count; });
  return count;
}

}  // namespace lastcut
