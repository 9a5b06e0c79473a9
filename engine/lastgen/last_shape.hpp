#pragma once
// The solid of a shoe last as an implicit function (negative inside, roughly a signed distance
// in mm near the surface), built like a last maker thinks of it:
//   plan outline (PlanOutline) extruded upwards, leaning inwards with height (the sides narrow
//   towards the top)  AND  below a crowned top line (toe box, vamp, instep rising to the back)
//   AND  above the sole line (flat tread at z = 0, toe spring in front, raised heel seat behind)
//   AND  below the flat top cut (the cone/thimble plane, about top_height above the heel seat).
// Each AND is a rounded intersection (fillet radius r: large on the instep dome, a few mm at the
// feather line, 2 mm at the top cut), after Quilez' rounded SDF booleans; the blends are smooth
// so the remesher can project onto the surface.
// Medial side is +Y here; generate_last mirrors for a left last.
#include <Eigen/Core>

#include "engine/lastgen/last_params.hpp"
#include "engine/lastgen/monotone_spline.hpp"
#include "engine/lastgen/plan_outline.hpp"

namespace lastcut {

class LastShape {
 public:
  explicit LastShape(const LastParams& params);

  // Implicit value at p (mm): < 0 inside, > 0 outside, |value| ~ distance near the surface.
  double value(const Eigen::Vector3d& p) const;
  // Central-difference gradient of value() (unitless, length ~ 1 near the surface).
  Eigen::Vector3d gradient(const Eigen::Vector3d& p) const;
  // Newton steps along the gradient to the zero level set (mm in, mm out).
  Eigen::Vector3d project(const Eigen::Vector3d& p) const;
  // The same for the body: the solid before the top cut (no cut, no 2 mm fillet). Its zero set
  // meets the cut plane in the sharp rim the Bezier surface keeps (engine/lastgen/last_side_mesh.hpp).
  double body_value(const Eigen::Vector3d& p) const;
  Eigen::Vector3d body_gradient(const Eigen::Vector3d& p) const;
  Eigen::Vector3d project_to_body(const Eigen::Vector3d& p) const;

  // Height of the sole (ground contact line) at x (mm); 0 on the ball tread.
  double sole_z_mm(double x_mm) const;
  // Height of the top cut plane at x (mm), and its outward (upward) unit normal.
  double top_cut_z_mm(double x_mm) const;
  Eigen::Vector3d top_cut_normal() const;
  // Axis-aligned box that contains the last, with a margin (mm): {min, max}.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> bounds_mm() const;

 private:
  using Field = double (LastShape::*)(const Eigen::Vector3d&) const;
  Eigen::Vector3d gradient_of(Field field, const Eigen::Vector3d& p) const;
  Eigen::Vector3d project_on(Field field, const Eigen::Vector3d& p) const;
  double sole_slope(double x_mm) const;
  double inset_mm(double height_above_sole_mm) const;

  LastParams params_;
  PlanOutline outline_;
  MonotoneSpline top_line_z_mm_;   // body top (before the cut) along x
  MonotoneSpline dome_radius_mm_;  // rounding of the section top along x
  double cut_z_at_origin_mm_ = 0.0, cut_slope_ = 0.0;
  double taper_at_cut_mm_ = 0.0;
};

}  // namespace lastcut
