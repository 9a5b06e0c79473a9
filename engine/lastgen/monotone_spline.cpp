#include "engine/lastgen/monotone_spline.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "engine/core/engine_error.hpp"

namespace lastcut {

MonotoneSpline::MonotoneSpline(std::vector<double> knots_x, std::vector<double> values)
    : x_(std::move(knots_x)), y_(std::move(values)), slope_(x_.size(), 0.0) {
  const size_t n = x_.size();
  if (n < 2 || y_.size() != n) throw EngineError("monotone spline needs at least two knots");
  std::vector<double> secant(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) {
    if (!(x_[i + 1] > x_[i])) throw EngineError("monotone spline knots must increase");
    secant[i] = (y_[i + 1] - y_[i]) / (x_[i + 1] - x_[i]);
  }
  slope_[0] = secant[0];
  slope_[n - 1] = secant[n - 2];
  for (size_t i = 1; i + 1 < n; ++i) {
    if (secant[i - 1] * secant[i] <= 0.0) continue;  // local extremum: flat tangent
    const double h0 = x_[i] - x_[i - 1], h1 = x_[i + 1] - x_[i];
    const double w0 = 2.0 * h1 + h0, w1 = h1 + 2.0 * h0;
    slope_[i] = (w0 + w1) / (w0 / secant[i - 1] + w1 / secant[i]);
  }
}

int MonotoneSpline::segment(double x) const {
  const auto upper = std::upper_bound(x_.begin(), x_.end(), x);
  const int index = static_cast<int>(upper - x_.begin()) - 1;
  return std::clamp(index, 0, static_cast<int>(x_.size()) - 2);
}

double MonotoneSpline::value(double x) const {
  if (x <= x_.front()) return y_.front();
  if (x >= x_.back()) return y_.back();
  const int i = segment(x);
  const double h = x_[i + 1] - x_[i];
  const double t = (x - x_[i]) / h;
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * y_[i] + (t3 - 2 * t2 + t) * h * slope_[i] + (-2 * t3 + 3 * t2) * y_[i + 1] +
         (t3 - t2) * h * slope_[i + 1];
}

double MonotoneSpline::derivative(double x) const {
  if (x <= x_.front() || x >= x_.back()) return 0.0;
  const int i = segment(x);
  const double h = x_[i + 1] - x_[i];
  const double t = (x - x_[i]) / h;
  const double t2 = t * t;
  return ((6 * t2 - 6 * t) * y_[i] + (6 * t - 6 * t2) * y_[i + 1]) / h + (3 * t2 - 4 * t + 1) * slope_[i] +
         (3 * t2 - 2 * t) * slope_[i + 1];
}

}  // namespace lastcut
