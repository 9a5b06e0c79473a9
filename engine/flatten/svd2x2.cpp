// Analytic 2x2 SVD (thesis Algorithm 1, corrected) and the closest rotation; see svd2x2.hpp.
#include "engine/flatten/svd2x2.hpp"

#include <algorithm>
#include <cmath>

namespace lastcut {

Svd2 svd2x2(const Eigen::Matrix2d& A_in) {
  Svd2 out;
  const double scale = A_in.cwiseAbs().maxCoeff();
  if (!(scale > 0.0) || !std::isfinite(scale)) {
    // Zero matrix (or non-finite input, which has no SVD): identity factors, zero singular values.
    out.U.setIdentity();
    out.V.setIdentity();
    out.sigma.setZero();
    if (!std::isfinite(scale)) out.sigma.setConstant(scale);
    return out;
  }
  const Eigen::Matrix2d A = A_in / scale;
  const double a11 = A(0, 0), a12 = A(0, 1), a21 = A(1, 0), a22 = A(1, 1);

  // Line 2-3: sigma11 = R + Q, sigma22 = |Q - R| with R, Q the half-radicals.
  const double R = 0.5 * std::hypot(a11 - a22, a12 + a21);
  const double Q = 0.5 * std::hypot(a11 + a22, a12 - a21);
  const double s1 = R + Q;
  const double s2 = std::abs(Q - R);

  // Line 4-6: V = [v11 v12; v21 v22] is the rotation whose first column (v11, v21) is the right singular
  // vector of s1. With M = A^T A = [p q; q r]: v11^2 = (s1^2 - r) / (s1^2 - s2^2) (line 4),
  // v21^2 = (s1^2 - p) / (s1^2 - s2^2) and v11 v21 = q / (s1^2 - s2^2), where s1^2 - s2^2 = 4 Q R exactly.
  // Taking the square root only of the larger component keeps both accurate to eps (a square root of a
  // tiny rounded value would only be accurate to sqrt(eps)); the sign of v21 is that of q (line 5).
  double v11 = 1.0, v21 = 0.0;
  if (s1 > s2) {
    const double p = a11 * a11 + a21 * a21, r = a12 * a12 + a22 * a22, q = a11 * a12 + a21 * a22;
    const double gap = 4.0 * Q * R;  // s1^2 - s2^2
    const double v11_sq = std::clamp((s1 * s1 - r) / gap, 0.0, 1.0);
    const double v21_sq = std::clamp((s1 * s1 - p) / gap, 0.0, 1.0);
    if (v11_sq >= v21_sq) {
      v11 = std::sqrt(v11_sq);
      v21 = q / (gap * v11);
    } else {
      v21 = std::copysign(std::sqrt(v21_sq), q);
      v11 = q / (gap * v21);
    }
    const double norm = std::hypot(v11, v21);
    v11 /= norm;
    v21 /= norm;
  }
  const double v12 = -v21;
  const double v22 = v11;

  // Line 7-8: u1 = A v1 / sigma11 (sigma11 = ||A|| > 0 here); renormalised against rounding.
  Eigen::Vector2d u1(a11 * v11 + a12 * v21, a21 * v11 + a22 * v21);
  const double u1_norm = u1.norm();
  if (u1_norm > 0.0) {
    u1 /= u1_norm;
  } else {
    u1 = Eigen::Vector2d(1.0, 0.0);
  }
  // Line 9-10 (corrected): u2 = sign(det A) * perp(u1).
  const double det_sign = (a11 * a22 - a12 * a21) < 0.0 ? -1.0 : 1.0;
  out.U << u1(0), -det_sign * u1(1), u1(1), det_sign * u1(0);
  out.V << v11, v12, v21, v22;
  out.sigma << s1 * scale, s2 * scale;
  return out;
}

Eigen::Matrix2d closest_rotation2x2(const Eigen::Matrix2d& S) {
  const double a = S(0, 0) + S(1, 1);
  const double b = S(1, 0) - S(0, 1);
  const double n = std::hypot(a, b);
  Eigen::Matrix2d R;
  if (n > 0.0) {
    R << a / n, -b / n, b / n, a / n;
  } else {
    R.setIdentity();
  }
  return R;
}

}  // namespace lastcut
