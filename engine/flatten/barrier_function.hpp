#pragma once
// What the two barriers of bijective ARAP share (boundary_barrier.hpp, fold_barrier.hpp):
//  - the barrier function of J. Smith, S. Schaefer, "Bijective Parameterization with Free Boundaries",
//    SIGGRAPH 2015, eq. 4, also the shape of the area barrier of C. Schüller et al., "Locally Injective
//    Mappings", SGP 2013:
//      f(x) = weight * (reach / x - 1)^2   for 0 < x < reach (0 above),
//    smooth at x = reach (value and slope vanish there) and infinite as x -> 0;
//  - the form in which both hand their curvature to the step's linear system.

namespace lastcut {

// f, f' and f'' at x (0 < x < reach); weight in the energy's unit (mm^2), reach and x in one unit.
struct BarrierValue {
  double value, slope, curvature;
};
inline BarrierValue barrier_at(double weight, double reach, double x) {
  const double excess = reach / x - 1.0;
  return {weight * excess * excess, -2.0 * weight * excess * reach / (x * x),
          2.0 * weight * reach * reach / (x * x * x * x) + 4.0 * weight * reach * excess / (x * x * x)};
}

// One rank-one term of a barrier's curvature bound: curvature * (w . dU)^2 over three vertices, the same
// for the u and the v column (each barrier says why its terms bound its Gauss-Newton curvature from above).
struct BarrierCurvature {
  int vertex[3];
  double weight[3];
  double curvature;
};

}  // namespace lastcut
