#include "engine/lastgen/last_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace lastcut {
namespace {

// Rounded intersection of two (approximate) signed distances with fillet radius r (mm).
double round_intersection(double a, double b, double r) {
  const double u = std::max(a + r, 0.0), v = std::max(b + r, 0.0);
  return std::min(-r, std::max(a, b)) + std::hypot(u, v);
}

constexpr double kFeatherRadiusMm = 4.0;  // sole-to-side fillet along the feather line
constexpr double kTopCutRadiusMm = 2.0;   // edge of the cone cut
constexpr double kTopCutTiltDeg = 3.0;    // the cut plane rises slightly towards the front
constexpr double kCrownDropFraction = 0.22;  // how much lower the top is at the sides than on the centre line

MonotoneSpline make_top_line(const LastParams& p, const LastShape& shape, double cut_z_mm) {
  const double L = p.length_mm;
  // Height of the body above the sole in front (fractions of the length), then above the cut
  // behind so that the cut makes the flat top.
  const std::vector<std::pair<double, double>> front{
      {1.00, 0.060}, {0.93, 0.092}, {0.85, 0.132}, {0.75, 0.188}, {0.65, 0.250}, {0.55, 0.330}, {0.46, 0.420}};
  std::vector<double> xs, zs;
  xs.push_back(-0.10 * L);
  zs.push_back(cut_z_mm + 30.0);
  xs.push_back(0.25 * L);
  zs.push_back(cut_z_mm + 30.0);
  xs.push_back(0.37 * L);
  zs.push_back(cut_z_mm + 16.0);
  for (auto it = front.rbegin(); it != front.rend(); ++it) {
    xs.push_back(it->first * L);
    zs.push_back(shape.sole_z_mm(it->first * L) + it->second * L);
  }
  xs.push_back(1.10 * L);
  zs.push_back(zs.back());
  // Keep the profile monotone: the top line only falls from the back to the front.
  for (size_t i = 1; i < zs.size(); ++i) zs[i] = std::min(zs[i], zs[i - 1] - 1e-3);
  return MonotoneSpline(xs, zs);
}

}  // namespace

LastShape::LastShape(const LastParams& params)
    : params_(params), outline_(params), top_line_z_mm_({0.0, 1.0}, {0.0, 0.0}), dome_radius_mm_({0.0, 1.0}, {0.0, 0.0}) {
  const double L = params.length_mm;
  cut_slope_ = std::tan(kTopCutTiltDeg * std::numbers::pi / 180.0);
  // The cut passes top_height above the heel seat over the heel (x = 0.2 L).
  cut_z_at_origin_mm_ = params.heel_height_mm + params.top_height_mm - cut_slope_ * 0.2 * L;
  top_line_z_mm_ = make_top_line(params, *this, top_cut_z_mm(0.3 * L));
  // The sides lean in so that the cut face is ~ 0.6 heel widths across (35-45 mm).
  taper_at_cut_mm_ = 0.17 * params.heel_width_mm;
  dome_radius_mm_ = MonotoneSpline({0.40 * L, 0.55 * L, 0.75 * L, 0.92 * L, 1.0 * L},
                                   {0.090 * L, 0.075 * L, 0.060 * L, 0.040 * L, 0.032 * L});
}

double LastShape::sole_z_mm(double x_mm) const {
  const double L = params_.length_mm;
  const double t = x_mm / L;
  // Raised heel seat behind 0.18 L, shank curve down to the tread at 0.60 L, flat tread to 0.74 L,
  // toe spring rising to the tip.
  if (t <= 0.18) return params_.heel_height_mm;
  if (t < 0.60) return params_.heel_height_mm * 0.5 * (1.0 + std::cos(std::numbers::pi * (t - 0.18) / 0.42));
  if (t <= 0.74) return 0.0;
  return params_.toe_spring_mm * std::pow(std::min(t, 1.1) - 0.74, 2.2) / std::pow(0.26, 2.2);
}

double LastShape::sole_slope(double x_mm) const {
  const double h = 0.05;
  return (sole_z_mm(x_mm + h) - sole_z_mm(x_mm - h)) / (2 * h);
}

double LastShape::top_cut_z_mm(double x_mm) const { return cut_z_at_origin_mm_ + cut_slope_ * x_mm; }

Eigen::Vector3d LastShape::top_cut_normal() const { return Eigen::Vector3d(-cut_slope_, 0.0, 1.0).normalized(); }

double LastShape::inset_mm(double height_above_sole_mm) const {
  const double h = std::max(height_above_sole_mm, 0.0) / params_.top_height_mm;
  return taper_at_cut_mm_ * std::pow(h, 1.6);
}

double LastShape::value(const Eigen::Vector3d& p) const {
  const double cut = (p.z() - top_cut_z_mm(p.x())) / std::sqrt(1.0 + cut_slope_ * cut_slope_);
  return round_intersection(body_value(p), cut, kTopCutRadiusMm);
}

double LastShape::body_value(const Eigen::Vector3d& p) const {
  const double x = p.x(), y = p.y(), z = p.z();
  const double sole_z = sole_z_mm(x);
  const double height = z - sole_z;

  // Sides: plan outline, moved inwards with height.
  const double sides = outline_.signed_distance_mm(x, y) + inset_mm(height);

  // Crowned top line: lower towards the sides of the section.
  const Eigen::Vector2d span = outline_.y_span_mm(x);
  const double centre_y = 0.5 * (span.x() + span.y());
  const double half_width = std::max(0.5 * (span.y() - span.x()), 0.25 * params_.ball_width_mm);
  const double body_top = top_line_z_mm_.value(x);
  const double crown_scale = kCrownDropFraction * std::max(body_top - sole_z, 10.0) / (half_width * half_width);
  const double dy = y - centre_y;
  const double top_z = body_top - crown_scale * dy * dy;
  const double slope_x = top_line_z_mm_.derivative(x), slope_y = -2.0 * crown_scale * dy;
  const double top = (z - top_z) / std::sqrt(1.0 + slope_x * slope_x + slope_y * slope_y);

  double solid = round_intersection(sides, top, dome_radius_mm_.value(x));

  // Sole: everything above the sole line.
  const double sole_slope_x = sole_slope(x);
  const double sole = -height / std::sqrt(1.0 + sole_slope_x * sole_slope_x);
  return round_intersection(solid, sole, kFeatherRadiusMm);
}

Eigen::Vector3d LastShape::gradient(const Eigen::Vector3d& p) const { return gradient_of(&LastShape::value, p); }
Eigen::Vector3d LastShape::body_gradient(const Eigen::Vector3d& p) const { return gradient_of(&LastShape::body_value, p); }
Eigen::Vector3d LastShape::project(const Eigen::Vector3d& p) const { return project_on(&LastShape::value, p); }
Eigen::Vector3d LastShape::project_to_body(const Eigen::Vector3d& p) const { return project_on(&LastShape::body_value, p); }

Eigen::Vector3d LastShape::gradient_of(Field field, const Eigen::Vector3d& p) const {
  constexpr double h = 0.2;
  Eigen::Vector3d g;
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::Vector3d step = Eigen::Vector3d::Zero();
    step(axis) = h;
    g(axis) = ((this->*field)(p + step) - (this->*field)(p - step)) / (2 * h);
  }
  return g;
}

Eigen::Vector3d LastShape::project_on(Field field, const Eigen::Vector3d& p) const {
  Eigen::Vector3d q = p;
  for (int step = 0; step < 8; ++step) {
    const double f = (this->*field)(q);
    if (std::abs(f) < 1e-4) break;
    const Eigen::Vector3d g = gradient_of(field, q);
    const double g2 = g.squaredNorm();
    if (g2 < 1e-12) break;
    Eigen::Vector3d move = -f * g / g2;
    const double length = move.norm();
    if (length > 5.0) move *= 5.0 / length;  // never jump across the solid
    q += move;
  }
  return q;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> LastShape::bounds_mm() const {
  const double L = params_.length_mm, W = params_.ball_width_mm;
  const double top = std::max(top_cut_z_mm(0.0), top_cut_z_mm(L)) + 10.0;
  return {Eigen::Vector3d(-10.0, -0.75 * W, -10.0), Eigen::Vector3d(L + 10.0, 0.75 * W, top)};
}

}  // namespace lastcut
