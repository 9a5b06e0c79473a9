// The local step of ARAP and the flip guard's triangle test; see arap_local_step.hpp.
#include "engine/flatten/arap_local_step.hpp"

#include <algorithm>
#include <cmath>

namespace lastcut {
namespace {

constexpr double kCollapsedAreaFraction = 0.05;  // see TriangleState

// Per corner j of each triangle, the constant 2-vector c_j = w_(j+1) e_(j+1) - w_(j+2) e_(j+2) (6 #F, mm):
// the cross-covariance is sum_j (u_j, v_j) against c_j and corner j's share of the right-hand side is R c_j,
// so the local step reads and writes each vertex once per triangle instead of once per edge end.
std::vector<double> corner_vectors(const TriangleFrames& frames) {
  const size_t face_count = frames.triangles.size();
  std::vector<double> corner(6 * face_count);
  for (size_t f = 0; f < face_count; ++f) {
    const double* w = &frames.half_weight[3 * f];
    const double* e = &frames.edge_local_mm[6 * f];
    for (int j = 0; j < 3; ++j) {
      const int plus = (j + 1) % 3, minus = (j + 2) % 3;
      corner[6 * f + 2 * j] = w[plus] * e[2 * plus] - w[minus] * e[2 * minus];
      corner[6 * f + 2 * j + 1] = w[plus] * e[2 * plus + 1] - w[minus] * e[2 * minus + 1];
    }
  }
  return corner;
}

}  // namespace

ArapLocalStep::ArapLocalStep(const TriangleFrames& frames, const ReducedLaplacian& laplacian)
    : frames_(frames), laplacian_(laplacian), corner_(corner_vectors(frames)) {
  const int pinned = laplacian.pinned;
  for (size_t f = 0; f < frames.triangles.size(); ++f) {
    const auto& t = frames.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const double w = frames.half_weight[3 * f + k];
      const double ex = frames.edge_local_mm[6 * f + 2 * k], ey = frames.edge_local_mm[6 * f + 2 * k + 1];
      constant_energy_ += w * (ex * ex + ey * ey);
      const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      if (a == pinned) pinned_coupling_.emplace_back(laplacian.row_of_vertex[b], w);
      if (b == pinned) pinned_coupling_.emplace_back(laplacian.row_of_vertex[a], w);
    }
  }
}

double ArapLocalStep::run(const Eigen::MatrixXd& UV, std::vector<double>& rhs_vector) const {
  rhs_vector.assign(2 * static_cast<size_t>(UV.rows()), 0.0);
  double* rhs = rhs_vector.data();
  const double* u = UV.col(0).data();
  const double* v = UV.col(1).data();
  const double* weights = frames_.half_weight.data();
  const double* corners = corner_.data();
  double energy = constant_energy_;
  const size_t face_count = frames_.triangles.size();
  for (size_t f = 0; f < face_count; ++f) {
    const int i0 = frames_.triangles[f][0], i1 = frames_.triangles[f][1], i2 = frames_.triangles[f][2];
    const double u0 = u[i0], u1 = u[i1], u2 = u[i2], v0 = v[i0], v1 = v[i1], v2 = v[i2];
    const double* w = weights + 3 * f;
    const double* c = corners + 6 * f;
    const double a = u0 * c[0] + v0 * c[1] + u1 * c[2] + v1 * c[3] + u2 * c[4] + v2 * c[5];
    const double b = v0 * c[0] - u0 * c[1] + v1 * c[2] - u1 * c[3] + v2 * c[4] - u2 * c[5];
    // Edge k runs from t[k+1] to t[k+2].
    const double du0 = u2 - u1, du1 = u0 - u2, du2 = u1 - u0;
    const double dv0 = v2 - v1, dv1 = v0 - v2, dv2 = v1 - v0;
    const double squared = w[0] * (du0 * du0 + dv0 * dv0) + w[1] * (du1 * du1 + dv1 * dv1) +
                           w[2] * (du2 * du2 + dv2 * dv2);
    // Closest rotation [cs -sn; sn cs] to S (closest_rotation2x2, inlined: this loop is the hot path).
    const double norm = std::sqrt(a * a + b * b);
    const double cs = norm > 0.0 ? a / norm : 1.0;
    const double sn = norm > 0.0 ? b / norm : 0.0;
    energy += squared - 2.0 * norm;
    rhs[2 * i0] += cs * c[0] - sn * c[1];
    rhs[2 * i0 + 1] += sn * c[0] + cs * c[1];
    rhs[2 * i1] += cs * c[2] - sn * c[3];
    rhs[2 * i1 + 1] += sn * c[2] + cs * c[3];
    rhs[2 * i2] += cs * c[4] - sn * c[5];
    rhs[2 * i2 + 1] += sn * c[4] + cs * c[5];
  }
  return std::max(energy, 0.0);
}

void ArapLocalStep::reduce(const std::vector<double>& rhs, const Eigen::MatrixXd& UV,
                           Eigen::MatrixXd& reduced_rhs) const {
  reduced_rhs.resize(laplacian_.matrix.rows(), 2);
  for (Eigen::Index r = 0; r < reduced_rhs.rows(); ++r) {
    const int v = laplacian_.vertex_of_row[r];
    reduced_rhs(r, 0) = rhs[2 * v];
    reduced_rhs(r, 1) = rhs[2 * v + 1];
  }
  const int pinned = laplacian_.pinned;
  for (const auto& [row, w] : pinned_coupling_) {
    reduced_rhs(row, 0) += w * UV(pinned, 0);
    reduced_rhs(row, 1) += w * UV(pinned, 1);
  }
}

void ArapLocalStep::expand(const Eigen::MatrixXd& solution, const Eigen::MatrixXd& UV, Eigen::MatrixXd& out) const {
  out.resize(UV.rows(), 2);
  out.row(laplacian_.pinned) = UV.row(laplacian_.pinned);
  for (Eigen::Index r = 0; r < solution.rows(); ++r) out.row(laplacian_.vertex_of_row[r]) = solution.row(r);
}

void classify_triangles(const TriangleFrames& frames, const Eigen::MatrixXd& UV, std::vector<char>& state) {
  const double* u = UV.col(0).data();
  const double* v = UV.col(1).data();
  state.resize(frames.triangles.size());
  for (size_t f = 0; f < frames.triangles.size(); ++f) {
    const auto& t = frames.triangles[f];
    const double ax = u[t[1]] - u[t[0]], ay = v[t[1]] - v[t[0]];
    const double bx = u[t[2]] - u[t[0]], by = v[t[2]] - v[t[0]];
    const double twice_area = ax * by - ay * bx;
    state[f] = twice_area <= 0.0 ? kFlipped
               : twice_area <= 2.0 * kCollapsedAreaFraction * frames.area_mm2(f) ? kCollapsed
                                                                                   : kHealthy;
  }
}

bool no_triangle_worse(const std::vector<char>& before, const std::vector<char>& after) {
  for (size_t f = 0; f < before.size(); ++f) {
    if (after[f] > before[f]) return false;
  }
  return true;
}

}  // namespace lastcut
