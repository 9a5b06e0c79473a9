#include "engine/orient/orient_last.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>

#include "engine/core/engine_error.hpp"
#include "engine/orient/principal_axes.hpp"

namespace lastcut {
namespace {

constexpr int kAngleBins = 360;
constexpr double kSoleToTopRatio = 1.3;       // how much more flat area the sole has than the top side
constexpr double kSoleToInstepWidthRatio = 1.08;  // how much wider a last is at the sole than over the instep
constexpr double kTopCutBandMm = 8.0;         // the top cut lies within this of the highest point
constexpr double kSmallestTopCutMm2 = 400.0;  // a flat top smaller than this does not set "up"

std::string format_double(double value, int decimals) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(decimals);
  out << value;
  return out.str();
}

// Direction around the long axis (angle in the plane of the two short axes) in which the sole
// faces. Normals are binned by that angle, weighted by area times the squared length of their
// component across the long axis, so the sole's toe spring and heel pitch (which tilt normals
// along the long axis only) keep it in one peak. The histogram then has four peaks: the two side
// walls, about as large as each other and roughly opposite; the sole; and opposite it the much
// smaller top (top cut and instep). So the sole is the peak that most outweighs the peak facing
// away from it. Returns the angle (rad) and that ratio.
std::pair<double, double> sole_direction(const TriMesh& mesh, const Eigen::MatrixXd& normals, const Eigen::VectorXd& areas,
                                         const Eigen::Vector3d& axis_b, const Eigen::Vector3d& axis_c) {
  std::array<double, kAngleBins> histogram{};
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d n = normals.row(f);
    const double pb = n.dot(axis_b), pc = n.dot(axis_c);
    const double across_squared = pb * pb + pc * pc;
    if (across_squared < 1e-12) continue;
    double angle_deg = std::atan2(pc, pb) * 180.0 / std::numbers::pi;
    if (angle_deg < 0.0) angle_deg += 360.0;
    histogram[static_cast<std::size_t>(angle_deg) % kAngleBins] += areas(f) * across_squared;
  }
  auto at = [](const std::array<double, kAngleBins>& values, int bin) {
    return values[static_cast<std::size_t>(((bin % kAngleBins) + kAngleBins) % kAngleBins)];
  };
  constexpr int kHalfWindowDeg = 10, kPeakSeparationDeg = 20, kOppositeToleranceDeg = 35;
  std::array<double, kAngleBins> smoothed{};
  for (int bin = 0; bin < kAngleBins; ++bin)
    for (int k = -kHalfWindowDeg; k <= kHalfWindowDeg; ++k) smoothed[static_cast<std::size_t>(bin)] += at(histogram, bin + k);
  const double highest = *std::max_element(smoothed.begin(), smoothed.end());
  std::vector<int> peaks;
  for (int bin = 0; bin < kAngleBins; ++bin) {
    bool is_peak = at(smoothed, bin) >= 0.05 * highest;
    for (int k = 1; k <= kPeakSeparationDeg && is_peak; ++k)
      is_peak = at(smoothed, bin) > at(smoothed, bin - k) && at(smoothed, bin) >= at(smoothed, bin + k);
    if (is_peak) peaks.push_back(bin);
  }
  int best = 0;
  double best_ratio = 0.0;
  for (int peak : peaks) {
    if (at(smoothed, peak) < 0.3 * highest) continue;  // the sole is one of the big flat sets
    double opposite = at(smoothed, peak + kAngleBins / 2);
    for (int other : peaks) {
      const int separation = std::abs(other - peak);
      if (std::abs(std::min(separation, kAngleBins - separation) - kAngleBins / 2) <= kOppositeToleranceDeg)
        opposite = std::max(opposite, at(smoothed, other));
    }
    const double ratio = at(smoothed, peak) / std::max(opposite, 1e-12 * highest);
    if (ratio > best_ratio) { best_ratio = ratio; best = peak; }
  }
  return {(best + 0.5) * std::numbers::pi / 180.0, best_ratio};
}

// Area-weighted sum of the normals within cone_deg of axis (restricted to faces with
// only[f] != 0 when `only` is not empty). Its length is about the area of those faces (mm^2).
Eigen::Vector3d mean_normal_in_cone(const Eigen::MatrixXd& normals, const Eigen::VectorXd& areas, const Eigen::Vector3d& axis,
                                    double cone_deg, const std::vector<char>& only) {
  const double cone_cos = std::cos(cone_deg * std::numbers::pi / 180.0);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (Eigen::Index f = 0; f < normals.rows(); ++f) {
    if (!only.empty() && !only[static_cast<std::size_t>(f)]) continue;
    const Eigen::Vector3d n = normals.row(f);
    if (n.dot(axis) > cone_cos) sum += areas(f) * n;
  }
  return sum;
}

// Width of the surface near the bottom and near the top of the middle of the last, for a
// candidate up direction: a last (and a foot) is wide at the sole and narrower over the instep.
// The middle 30-70 % of the length is cut into slabs; in each, the vertices in the lowest and
// in the highest quarter of the slab's height are measured across. Returns bottom / top width.
double bottom_to_top_width_ratio(const TriMesh& mesh, const Eigen::Vector3d& along_axis, const Eigen::Vector3d& up) {
  const Eigen::Vector3d across = up.cross(along_axis).normalized();
  const Eigen::VectorXd s = mesh.V * along_axis, h = mesh.V * up, w = mesh.V * across;
  const double s_min = s.minCoeff(), length = s.maxCoeff() - s_min;
  constexpr int kSlabs = 5;
  double bottom_width = 0.0, top_width = 0.0;
  for (int slab = 0; slab < kSlabs; ++slab) {
    const double from = s_min + (0.3 + 0.4 * slab / kSlabs) * length, to = from + 0.4 * length / kSlabs;
    double h_low = 1e300, h_high = -1e300;
    for (Eigen::Index v = 0; v < s.size(); ++v)
      if (s(v) >= from && s(v) < to) { h_low = std::min(h_low, h(v)); h_high = std::max(h_high, h(v)); }
    if (h_high <= h_low) continue;
    const double band = 0.25 * (h_high - h_low);
    double bottom_min = 1e300, bottom_max = -1e300, top_min = 1e300, top_max = -1e300;
    for (Eigen::Index v = 0; v < s.size(); ++v) {
      if (s(v) < from || s(v) >= to) continue;
      if (h(v) < h_low + band) { bottom_min = std::min(bottom_min, w(v)); bottom_max = std::max(bottom_max, w(v)); }
      if (h(v) > h_high - band) { top_min = std::min(top_min, w(v)); top_max = std::max(top_max, w(v)); }
    }
    bottom_width += bottom_max - bottom_min;
    top_width += top_max - top_min;
  }
  return top_width > 0.0 ? bottom_width / top_width : 1.0;
}

struct EndHeights {
  double at_min_end_mm;
  double at_max_end_mm;
};

// Height above the lowest point of the tallest vertex in the first and last 15 % of the length.
EndHeights end_heights(const Eigen::MatrixXd& along, const Eigen::VectorXd& up) {
  const double min_s = along.minCoeff(), max_s = along.maxCoeff(), length = max_s - min_s;
  const double floor = up.minCoeff();
  EndHeights heights{0.0, 0.0};
  for (Eigen::Index v = 0; v < along.rows(); ++v) {
    if (along(v) < min_s + 0.15 * length) heights.at_min_end_mm = std::max(heights.at_min_end_mm, up(v) - floor);
    if (along(v) > max_s - 0.15 * length) heights.at_max_end_mm = std::max(heights.at_max_end_mm, up(v) - floor);
  }
  return heights;
}

// Area-weighted mean Y of the faces whose centroid lies in [x_from, x_to] (canonical frame).
double mean_y_between(const TriMesh& mesh, const Eigen::VectorXd& areas, double x_from, double x_to) {
  double weight = 0.0, sum = 0.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d g = (mesh.V.row(mesh.F(f, 0)) + mesh.V.row(mesh.F(f, 1)) + mesh.V.row(mesh.F(f, 2))) / 3.0;
    if (g.x() < x_from || g.x() > x_to) continue;
    weight += areas(f);
    sum += areas(f) * g.y();
  }
  return weight > 0.0 ? sum / weight : 0.0;
}

}  // namespace

OrientedLast orient_last(const TriMesh& scan, std::optional<FootSide> named_side) {
  if (scan.F.rows() < 100 || scan.V.rows() < 50)
    throw EngineError("the scan has only " + std::to_string(scan.F.rows()) + " triangles: too coarse to be a last");
  const PrincipalAxes principal = principal_axes(scan);
  if (principal.spread(0) < 1.3 * principal.spread(1))
    throw EngineError("the scan has no clear long axis (length spread " + format_double(principal.spread(0), 1) +
                      " mm vs " + format_double(principal.spread(1), 1) + " mm): not a last");
  OrientedLast result;
  const Eigen::MatrixXd normals = triangle_normals(scan);
  const Eigen::VectorXd areas = triangle_areas(scan);

  // Which way is up: the sole is the largest near-flat face set, and it faces down.
  const Eigen::Vector3d long_axis = principal.axes.col(0);
  const auto [sole_angle, sole_ratio] =
      sole_direction(scan, normals, areas, principal.axes.col(1), principal.axes.col(2));
  Eigen::Vector3d rough_down =
      std::cos(sole_angle) * principal.axes.col(1) + std::sin(sole_angle) * principal.axes.col(2);
  if (sole_ratio < kSoleToTopRatio)
    throw EngineError("cannot tell the sole from the top: the largest flat side is only " + format_double(sole_ratio, 2) +
                      "x the side opposite it");
  // The flat-area imbalance finds the up-down axis; which end of it is the sole is told by width:
  // the sole is wide, the instep narrow (a foot's curved arch can make the sole the smaller flat side).
  double width_ratio = bottom_to_top_width_ratio(scan, long_axis, -rough_down);
  if (width_ratio < 1.0) {
    rough_down = -rough_down;
    width_ratio = 1.0 / width_ratio;
  }
  if (width_ratio < kSoleToInstepWidthRatio)
    throw EngineError("cannot tell the sole from the top: the last is as wide at the bottom as at the top (" +
                      format_double(width_ratio, 2) + "x)");
  result.notes.push_back("sole: on the up-down axis (flat sides " + format_double(sole_ratio, 1) +
                         "x unequal), the side " + format_double(width_ratio, 2) + "x wider than the instep");

  // Refine up. The sole is curved (heel pitch, toe spring), so its mean normal leans towards the
  // toe; the top cut is a plane nearly level in the wearing position, so when it is found its
  // normal is the better "up".
  const Eigen::Vector3d sole_up = -mean_normal_in_cone(normals, areas, rough_down, 30.0, {}).normalized();
  Eigen::VectorXd face_height(scan.F.rows());
  for (Eigen::Index f = 0; f < scan.F.rows(); ++f)
    face_height(f) = (scan.V.row(scan.F(f, 0)) + scan.V.row(scan.F(f, 1)) + scan.V.row(scan.F(f, 2))).dot(sole_up) / 3.0;
  std::vector<char> near_top(static_cast<std::size_t>(scan.F.rows()));
  const double highest = face_height.maxCoeff();
  for (Eigen::Index f = 0; f < scan.F.rows(); ++f)
    near_top[static_cast<std::size_t>(f)] = face_height(f) > highest - kTopCutBandMm;
  Eigen::Vector3d up = sole_up;
  double top_area = 0.0;
  for (int round = 0; round < 2; ++round) {
    const Eigen::Vector3d top_sum = mean_normal_in_cone(normals, areas, up, 20.0, near_top);
    top_area = top_sum.norm();
    if (top_area < kSmallestTopCutMm2) break;
    up = top_sum.normalized();
  }
  if (up == sole_up)
    result.notes.push_back("up: mean sole normal (no flat top cut of " + format_double(kSmallestTopCutMm2, 0) + " mm^2 found)");
  else
    result.notes.push_back("up: normal of the top cut (" + format_double(top_area, 0) + " mm^2), " +
                           format_double(std::acos(std::clamp(up.dot(sole_up), -1.0, 1.0)) * 180.0 / std::numbers::pi, 1) +
                           " deg from the mean sole normal");
  Eigen::Vector3d toe_axis = (long_axis - long_axis.dot(up) * up).normalized();

  // Toe or heel: the heel end of a last is much taller than the toe end.
  Eigen::VectorXd along(scan.V.rows()), height(scan.V.rows());
  for (Eigen::Index v = 0; v < scan.V.rows(); ++v) {
    const Eigen::Vector3d p = Eigen::Vector3d(scan.V.row(v)) - principal.centroid;
    along(v) = p.dot(toe_axis);
    height(v) = p.dot(up);
  }
  const EndHeights heights = end_heights(along, height);
  const double taller = std::max(heights.at_min_end_mm, heights.at_max_end_mm);
  const double shorter = std::min(heights.at_min_end_mm, heights.at_max_end_mm);
  if (taller < 1.15 * shorter)
    throw EngineError("cannot tell toe from heel: both ends are about as tall (" + format_double(heights.at_min_end_mm, 0) +
                      " mm and " + format_double(heights.at_max_end_mm, 0) + " mm)");
  if (heights.at_max_end_mm > heights.at_min_end_mm) toe_axis = -toe_axis;
  result.notes.push_back("heel: the end " + format_double(taller, 0) + " mm tall; toe: the end " +
                         format_double(shorter, 0) + " mm tall");

  Eigen::Matrix3d rotation;
  rotation.row(0) = toe_axis.transpose();
  rotation.row(1) = up.cross(toe_axis).transpose();
  rotation.row(2) = up.transpose();
  Eigen::MatrixXd canonical = (scan.V.rowwise() - principal.centroid.transpose()) * rotation.transpose();
  const Eigen::RowVector3d shift(-canonical.col(0).minCoeff(), 0.0, -canonical.col(2).minCoeff());
  canonical.rowwise() += shift;
  result.mesh.V = canonical;
  result.mesh.F = scan.F;

  // Centre the heel on y = 0, then the toe tip leans towards the medial side.
  const double length = canonical.col(0).maxCoeff();
  const double heel_y = mean_y_between(result.mesh, areas, 0.0, 0.2 * length);
  result.mesh.V.col(1).array() -= heel_y;
  const double toe_y = mean_y_between(result.mesh, areas, 0.85 * length, length);
  const double toe_offset_mm = toe_y;
  const std::string lean = format_double(std::abs(toe_offset_mm), 1) + " mm to " + (toe_offset_mm < 0.0 ? "-Y" : "+Y");
  if (std::abs(toe_offset_mm) < kSymmetricToeOffsetShare * length) {
    if (named_side) {
      result.side = *named_side;
      result.notes.push_back("side: " + std::string(to_string(result.side)) + " as named; the last is symmetric (toe off the heel's line by " +
                             lean + ")");
    } else {
      result.side = FootSide::Left;
      result.side_unnamed = true;
      result.warnings.push_back(std::string("symmetric last: the side was not named, halves named ") + kNeutralHalfPlusY +
                                " and " + kNeutralHalfMinusY + "; give --side or the sidecar's side to name them medial/lateral");
      result.notes.push_back(result.warnings.back() + " (toe off the heel's line by " + lean + ")");
    }
  } else {
    result.side = toe_offset_mm < 0.0 ? FootSide::Left : FootSide::Right;
    result.notes.push_back(std::string("side: ") + std::string(to_string(result.side)) + ", toe leans " + lean);
    if (named_side && *named_side != result.side) {
      result.warnings.push_back("the side named is " + std::string(to_string(*named_side)) + " but the scan is a " +
                                std::string(to_string(result.side)) + " last (toe leans " + lean +
                                "): the halves are named for a " + std::string(to_string(result.side)) + " last");
      result.notes.push_back(result.warnings.back());
    }
  }

  result.scan_to_canonical = Eigen::Affine3d::Identity();
  result.scan_to_canonical.linear() = rotation;
  result.scan_to_canonical.translation() =
      -rotation * principal.centroid + Eigen::Vector3d(shift(0), -heel_y, shift(2));
  return result;
}

}  // namespace lastcut
