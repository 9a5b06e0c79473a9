#pragma once
// Monotone piecewise-cubic Hermite interpolation of a 1D profile (no overshoot between knots):
//   Fritsch & Carlson, "Monotone piecewise cubic interpolation", SIAM J. Numer. Anal. 17(2), 1980.
// Outside the knot range the end values are held constant.
#include <vector>

namespace lastcut {

class MonotoneSpline {
 public:
  // knots_x strictly increasing, same size as values (>= 2).
  MonotoneSpline(std::vector<double> knots_x, std::vector<double> values);
  double value(double x) const;
  double derivative(double x) const;

 private:
  int segment(double x) const;
  std::vector<double> x_, y_, slope_;
};

}  // namespace lastcut
