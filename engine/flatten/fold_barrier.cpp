// The fold barrier of bijective ARAP (Schüller et al. 2013); see fold_barrier.hpp.
#include "engine/flatten/fold_barrier.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include "engine/core/engine_error.hpp"

namespace lastcut {

namespace {

// Twice the signed area of triangle t under UV (mm^2).
double twice_signed_area(const std::array<int, 3>& t, const double* u, const double* v) {
  return (u[t[1]] - u[t[0]]) * (v[t[2]] - v[t[0]]) - (v[t[1]] - v[t[0]]) * (u[t[2]] - u[t[0]]);
}

}  // namespace

FoldBarrier::FoldBarrier(const TriangleFrames& frames, const Eigen::MatrixXd& start, double activation_ratio,
                         double stiffness)
    : frames_(frames), stiffness_(stiffness) {
  if (!(activation_ratio > 0.0) || !(stiffness_ > 0.0))
    throw EngineError("flatten: the fold barrier needs a positive threshold and stiffness");
  activation_ratio_.resize(frames.triangles.size());
  for (size_t f = 0; f < frames.triangles.size(); ++f) {
    const double ratio = twice_signed_area(frames.triangles[f], start.col(0).data(), start.col(1).data()) /
                         (2.0 * frames.area_mm2(static_cast<Eigen::Index>(f)));
    activation_ratio_[f] = std::min(activation_ratio, 0.5 * ratio);
  }
}

template <typename Visit>
void FoldBarrier::for_each_active_triangle(const Eigen::MatrixXd& UV, Visit visit) const {
  const double* u = UV.col(0).data();
  const double* v = UV.col(1).data();
  for (size_t f = 0; f < frames_.triangles.size(); ++f) {
    const auto& t = frames_.triangles[f];
    const double twice_area_3d = 2.0 * frames_.area_mm2(static_cast<Eigen::Index>(f));
    const double ratio = twice_signed_area(t, u, v) / twice_area_3d;
    if (ratio >= activation_ratio_[f]) continue;
    // d(twice_area)/du_k and /dv_k, divided by the 3D value: dr/du, dr/dv.
    const double q_u[3] = {(v[t[1]] - v[t[2]]) / twice_area_3d, (v[t[2]] - v[t[0]]) / twice_area_3d,
                           (v[t[0]] - v[t[1]]) / twice_area_3d};
    const double q_v[3] = {(u[t[2]] - u[t[1]]) / twice_area_3d, (u[t[0]] - u[t[2]]) / twice_area_3d,
                           (u[t[1]] - u[t[0]]) / twice_area_3d};
    visit(f, ratio, q_u, q_v);
  }
}

double FoldBarrier::energy(const Eigen::MatrixXd& UV, std::vector<double>* gradient) const {
  double total = 0.0;
  for_each_active_triangle(UV, [&](size_t f, double r, const double* q_u, const double* q_v) {
    const double s = activation_ratio_[f];
    if (r <= 0.0) {
      total = std::numeric_limits<double>::infinity();
      return;
    }
    const BarrierValue barrier = barrier_at(stiffness_ * frames_.area_mm2(static_cast<Eigen::Index>(f)), s, r);
    total += barrier.value;
    if (gradient == nullptr) return;
    const double slope = barrier.slope;
    std::vector<double>& g = *gradient;
    for (int k = 0; k < 3; ++k) {
      const size_t vertex = static_cast<size_t>(frames_.triangles[f][k]);
      g[2 * vertex] += slope * q_u[k];
      g[2 * vertex + 1] += slope * q_v[k];
    }
  });
  return total;
}

void FoldBarrier::add_curvatures(const Eigen::MatrixXd& UV, std::vector<BarrierCurvature>& terms) const {
  for_each_active_triangle(UV, [&](size_t f, double r, const double* q_u, const double* q_v) {
    const double s = activation_ratio_[f];
    if (r <= 0.0) return;
    const double curvature = barrier_at(stiffness_ * frames_.area_mm2(static_cast<Eigen::Index>(f)), s, r).curvature;
    const auto& t = frames_.triangles[f];
    terms.push_back({{t[0], t[1], t[2]}, {q_u[0], q_u[1], q_u[2]}, 2.0 * curvature});
    terms.push_back({{t[0], t[1], t[2]}, {q_v[0], q_v[1], q_v[2]}, 2.0 * curvature});
  });
}

}  // namespace lastcut
