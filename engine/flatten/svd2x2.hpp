#pragma once
// Analytic singular value decomposition of a real 2x2 matrix and the closest rotation to it.
//
// svd2x2 follows Algorithm 1 of M. Sabaliauskas, "Computerized modeling technology of unique footwear
// surface manufacturing design", doctoral thesis summary, Vilnius University 2017, section 2.3.1,
// with these corrections to the published pseudo-code (each one is exact in exact arithmetic):
//  - line 10 assigns u11 <- u22 in the singular case; u22 <- u11 is meant (u2 = perp(u1)).
//  - lines 9-10 divide by sigma22, which amplifies rounding by sigma11/sigma22 for nearly singular A and
//    leaves U non-orthogonal; we use the identity u2 = sign(det A) * perp(u1) instead (V is a rotation,
//    so det U = sign(det A)). The same formula covers the singular case of lines 9-10.
//  - line 4's ratio (sigma11^2 - a12^2 - a22^2) / (sigma11^2 - sigma22^2) can leave [0, 1] by rounding when
//    sigma11 ~ sigma22 (nearly conformal A, the usual case in ARAP); it is clamped to [0, 1].
//  - line 3 computes sigma22 = |sigma11 - 2R| by cancellation; |Q - R| (Q, R the two half-radicals of
//    line 2) is the same value with one rounding less.
//  - A is scaled by its largest entry first so squares neither overflow nor underflow.
#include <Eigen/Core>

namespace lastcut {

// A = U * diag(sigma) * V^T with U, V orthonormal, sigma(0) >= sigma(1) >= 0.
// V is always a rotation (det V = +1); det U = sign(det A) (+1 for singular A).
struct Svd2 {
  Eigen::Matrix2d U;
  Eigen::Vector2d sigma;
  Eigen::Matrix2d V;
};

// Thesis Algorithm 1 (corrected, see above). Accurate to a few ulps of the largest singular value.
Svd2 svd2x2(const Eigen::Matrix2d& A);

// The rotation R (det R = +1) maximising trace(R^T S), i.e. closest to S in the Frobenius norm.
// Equals U * diag(1, det(U V^T)) * V^T from svd2x2(S), which is how a reflection (det S < 0) is handled;
// computed in closed form (R = [a -b; b a] / |(a, b)| with a = S11 + S22, b = S21 - S12) because ARAP's
// local step calls it once per triangle per iteration. Identity for S with a = b = 0.
Eigen::Matrix2d closest_rotation2x2(const Eigen::Matrix2d& S);

}  // namespace lastcut
