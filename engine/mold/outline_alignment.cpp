#include "engine/mold/outline_alignment.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "engine/core/engine_error.hpp"
#include "engine/mold/outline_geometry.hpp"

namespace lastcut {

namespace {

constexpr double kIcpSampleStep_mm = 1.0;
constexpr int kIcpMaxIterations = 100;

Point2 mean(const std::vector<Point2>& points) {
  Point2 sum = Point2::Zero();
  for (const auto& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}

double mean_squared_distance(const std::vector<Point2>& points, const Polygon2& target,
                             const RigidTransform2& transform) {
  double sum = 0.0;
  for (const auto& p : points) sum += std::pow(closest_outline_point(target, transform.apply(p)).distance_mm, 2);
  return sum / static_cast<double>(points.size());
}

RigidTransform2 icp(const std::vector<Point2>& samples, const Polygon2& target, RigidTransform2 transform) {
  double previous = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration < kIcpMaxIterations; ++iteration) {
    std::vector<Point2> moved, matched;
    moved.reserve(samples.size());
    matched.reserve(samples.size());
    double error = 0.0;
    for (const auto& p : samples) {
      const Point2 q = transform.apply(p);
      const OutlinePoint nearest = closest_outline_point(target, q);
      matched.push_back(nearest.point);
      moved.push_back(p);
      error += nearest.distance_mm * nearest.distance_mm;
    }
    transform = fit_rigid(moved, matched);
    if (previous - error < 1e-9 * samples.size()) break;
    previous = error;
  }
  return transform;
}

Eigen::Matrix2d principal_axes(const std::vector<Point2>& points) {
  const Point2 center = mean(points);
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
  for (const auto& p : points) covariance += (p - center) * (p - center).transpose();
  Eigen::JacobiSVD<Eigen::Matrix2d> svd(covariance, Eigen::ComputeFullU);
  Eigen::Matrix2d axes = svd.matrixU();
  if (axes.determinant() < 0) axes.col(1) *= -1.0;
  return axes;
}

}  // namespace

RigidTransform2 fit_rigid(const std::vector<Point2>& from, const std::vector<Point2>& to) {
  if (from.size() != to.size() || from.size() < 2) throw EngineError("rigid fit needs two or more matched points");
  const Point2 from_center = mean(from);
  const Point2 to_center = mean(to);
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
  for (size_t i = 0; i < from.size(); ++i) covariance += (to[i] - to_center) * (from[i] - from_center).transpose();
  Eigen::JacobiSVD<Eigen::Matrix2d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix2d correction = Eigen::Matrix2d::Identity();
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0) correction(1, 1) = -1.0;
  RigidTransform2 transform;
  transform.rotation = svd.matrixU() * correction * svd.matrixV().transpose();
  transform.translation = to_center - transform.rotation * from_center;
  return transform;
}

Polygon2 transformed(const Polygon2& polygon, const RigidTransform2& transform) {
  Polygon2 result;
  result.points.reserve(polygon.points.size());
  for (const auto& p : polygon.points) result.points.push_back(transform.apply(p));
  return result;
}

std::vector<Point2> sample_outline(const Polygon2& polygon, double step_mm) {
  std::vector<Point2> samples;
  const auto& p = polygon.points;
  for (size_t i = 0; i < p.size(); ++i) {
    const Point2& a = p[i];
    const Point2& b = p[(i + 1) % p.size()];
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step_mm)));
    for (int k = 0; k < pieces; ++k) samples.push_back(a + (b - a) * (static_cast<double>(k) / pieces));
  }
  return samples;
}

RigidTransform2 align_molds(const Mold& moving, const Mold& fixed) {
  if (moving.outline.points.size() < 3 || fixed.outline.points.size() < 3)
    throw EngineError("cannot align molds without outlines");
  const std::vector<Point2> samples = sample_outline(moving.outline, kIcpSampleStep_mm);

  std::vector<RigidTransform2> starts;
  std::vector<Point2> from, to;
  for (const auto& a : moving.marks)
    for (const auto& b : fixed.marks)
      if (a.name == b.name) from.push_back(a.position_mm), to.push_back(b.position_mm);
  if (from.size() >= 2) {
    starts.push_back(fit_rigid(from, to));
  } else {
    const std::vector<Point2> fixed_samples = sample_outline(fixed.outline, kIcpSampleStep_mm);
    const Eigen::Matrix2d moving_axes = principal_axes(samples);
    const Eigen::Matrix2d fixed_axes = principal_axes(fixed_samples);
    for (double sign : {1.0, -1.0}) {
      RigidTransform2 start;
      start.rotation = sign * fixed_axes * moving_axes.transpose();
      start.translation = mean(fixed_samples) - start.rotation * mean(samples);
      starts.push_back(start);
    }
  }
  RigidTransform2 best;
  double best_error = std::numeric_limits<double>::infinity();
  for (const auto& start : starts) {
    const RigidTransform2 refined = icp(samples, fixed.outline, start);
    const double error = mean_squared_distance(samples, fixed.outline, refined);
    if (error < best_error) best_error = error, best = refined;
  }
  return best;
}

double hausdorff_distance_mm(const Polygon2& a, const Polygon2& b, double step_mm) {
  double distance = 0.0;
  for (const auto& p : sample_outline(a, step_mm)) distance = std::max(distance, closest_outline_point(b, p).distance_mm);
  for (const auto& p : sample_outline(b, step_mm)) distance = std::max(distance, closest_outline_point(a, p).distance_mm);
  return distance;
}

}  // namespace lastcut
