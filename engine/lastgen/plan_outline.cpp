#include "engine/lastgen/plan_outline.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "engine/core/polygon.hpp"
#include "engine/lastgen/last_params.hpp"

namespace lastcut {
namespace {

// Centripetal Catmull-Rom point between p1 and p2 (u in [0, 1]).
Eigen::Vector2d catmull_rom(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& p2,
                            const Eigen::Vector2d& p3, double u) {
  const double t0 = 0.0;
  const double t1 = t0 + std::sqrt((p1 - p0).norm());
  const double t2 = t1 + std::sqrt((p2 - p1).norm());
  const double t3 = t2 + std::sqrt((p3 - p2).norm());
  const double t = t1 + u * (t2 - t1);
  const Eigen::Vector2d a1 = (t1 - t) / (t1 - t0) * p0 + (t - t0) / (t1 - t0) * p1;
  const Eigen::Vector2d a2 = (t2 - t) / (t2 - t1) * p1 + (t - t1) / (t2 - t1) * p2;
  const Eigen::Vector2d a3 = (t3 - t) / (t3 - t2) * p2 + (t - t2) / (t3 - t2) * p3;
  const Eigen::Vector2d b1 = (t2 - t) / (t2 - t0) * a1 + (t - t0) / (t2 - t0) * a2;
  const Eigen::Vector2d b2 = (t3 - t) / (t3 - t1) * a2 + (t - t1) / (t3 - t1) * a3;
  return (t2 - t) / (t2 - t1) * b1 + (t - t1) / (t2 - t1) * b2;
}

// Control points, medial side +Y: x as a fraction of the length, y in mm from the heel/ball
// widths. Heel points (x <= 0.3) scale with the heel width, the rest with the ball width.
std::vector<Eigen::Vector2d> control_points(const LastParams& p) {
  const double L = p.length_mm, W = p.ball_width_mm, H = p.heel_width_mm;
  const double heel_centre = -0.03 * H;  // the heel sits slightly lateral of the long axis
  const std::array<std::array<double, 3>, 25> table{{
      // {x / L, y, 0 = heel-width units around heel centre / 1 = ball-width units}
      {0.000, 0.00, 0}, {0.025, 0.34, 0}, {0.080, 0.465, 0}, {0.170, 0.50, 0}, {0.280, 0.48, 0},
      {0.400, 0.285, 1}, {0.500, 0.315, 1}, {0.600, 0.40, 1}, {0.710, 0.47, 1}, {0.800, 0.465, 1},
      {0.890, 0.40, 1}, {0.955, 0.28, 1}, {0.990, 0.15, 1}, {1.000, 0.07, 1},
      {0.993, -0.05, 1}, {0.960, -0.17, 1}, {0.890, -0.32, 1}, {0.790, -0.455, 1}, {0.660, -0.53, 1},
      {0.550, -0.50, 1}, {0.420, -0.43, 1}, {0.280, -0.525, 0}, {0.170, -0.52, 0}, {0.080, -0.475, 0},
      {0.025, -0.34, 0},
  }};
  std::vector<Eigen::Vector2d> points;
  if (p.symmetric) {
    // The medial rows (heel back to just before the toe tip), then the same mirrored on the way back.
    constexpr size_t kMedialRows = 13;
    for (size_t i = 0; i < kMedialRows; ++i) points.emplace_back(table[i][0] * L, table[i][1] * (table[i][2] == 0 ? H : W));
    points.emplace_back(L, 0.0);
    for (size_t i = kMedialRows - 1; i > 0; --i) points.emplace_back(points[i].x(), -points[i].y());
    return points;
  }
  for (const auto& row : table) {
    const double y = row[2] == 0 ? heel_centre + row[1] * H : row[1] * W;
    points.emplace_back(row[0] * L, y);
  }
  return points;
}

}  // namespace

PlanOutline::PlanOutline(const LastParams& params) {
  const std::vector<Eigen::Vector2d> controls = control_points(params);
  const size_t n = controls.size();
  constexpr int samples_per_span = 24;
  for (size_t i = 0; i < n; ++i) {
    const auto& p0 = controls[(i + n - 1) % n];
    const auto& p1 = controls[i];
    const auto& p2 = controls[(i + 1) % n];
    const auto& p3 = controls[(i + 2) % n];
    for (int s = 0; s < samples_per_span; ++s) polygon_.push_back(catmull_rom(p0, p1, p2, p3, s / double(samples_per_span)));
  }
  // Exact extents: x in [0, length], width across Y = ball width.
  Eigen::Vector2d low(std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
  Eigen::Vector2d high = -low;
  for (const auto& q : polygon_) {
    low = low.cwiseMin(q);
    high = high.cwiseMax(q);
  }
  const double x_scale = params.length_mm / (high.x() - low.x());
  const double y_scale = params.ball_width_mm / (high.y() - low.y());
  for (auto& q : polygon_) q = Eigen::Vector2d((q.x() - low.x()) * x_scale, q.y() * y_scale);
  Polygon2 as_polygon{polygon_};
  make_counter_clockwise(as_polygon);
  polygon_ = as_polygon.points;

  const double margin_mm = 15.0;  // the surface never reaches further out than the outline
  grid_origin_mm_ = Eigen::Vector2d(-margin_mm, low.y() * y_scale - margin_mm);
  grid_nx_ = static_cast<int>(std::ceil((params.length_mm + 2 * margin_mm) / grid_step_mm_)) + 1;
  grid_ny_ = static_cast<int>(std::ceil((params.ball_width_mm + 2 * margin_mm) / grid_step_mm_)) + 1;
  fill_distance_grid(0.15 * params.length_mm);

  const int span_count = static_cast<int>(std::floor(params.length_mm)) + 1;
  y_span_by_mm_.assign(static_cast<size_t>(span_count), Eigen::Vector2d(0.0, 0.0));
  for (int xi = 0; xi < span_count; ++xi) {
    const double x = std::clamp(static_cast<double>(xi), 0.5, params.length_mm - 0.5);
    double y_low = std::numeric_limits<double>::max(), y_high = -y_low;
    for (size_t k = 0; k < polygon_.size(); ++k) {
      const auto& a = polygon_[k];
      const auto& b = polygon_[(k + 1) % polygon_.size()];
      if ((a.x() <= x) == (b.x() <= x)) continue;
      const double y = a.y() + (x - a.x()) / (b.x() - a.x()) * (b.y() - a.y());
      y_low = std::min(y_low, y);
      y_high = std::max(y_high, y);
    }
    if (y_low <= y_high) y_span_by_mm_[static_cast<size_t>(xi)] = Eigen::Vector2d(y_low, y_high);
  }
}

void PlanOutline::fill_distance_grid(double band_mm) {
  // Unsigned distance within `band_mm` of each outline segment (farther cells keep the band
  // value: nothing there is near the surface), then the sign row by row from the crossings.
  grid_distance_mm_.assign(static_cast<size_t>(grid_nx_) * grid_ny_, static_cast<float>(band_mm));
  const size_t n = polygon_.size();
  for (size_t k = 0, previous = n - 1; k < n; previous = k++) {
    const Eigen::Vector2d& a = polygon_[previous];
    const Eigen::Vector2d& b = polygon_[k];
    const Eigen::Vector2d ab = b - a;
    const Eigen::Vector2d low = (a.cwiseMin(b) - grid_origin_mm_).array() / grid_step_mm_ - band_mm / grid_step_mm_;
    const Eigen::Vector2d high = (a.cwiseMax(b) - grid_origin_mm_).array() / grid_step_mm_ + band_mm / grid_step_mm_;
    const int i0 = std::max(0, static_cast<int>(std::floor(low.x()))), i1 = std::min(grid_nx_ - 1, static_cast<int>(std::ceil(high.x())));
    const int j0 = std::max(0, static_cast<int>(std::floor(low.y()))), j1 = std::min(grid_ny_ - 1, static_cast<int>(std::ceil(high.y())));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const Eigen::Vector2d p = grid_origin_mm_ + grid_step_mm_ * Eigen::Vector2d(i, j);
        const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
        float& cell = grid_distance_mm_[static_cast<size_t>(j) * grid_nx_ + i];
        cell = std::min(cell, static_cast<float>((a + t * ab - p).norm()));
      }
  }
  std::vector<double> crossings;
  for (int j = 0; j < grid_ny_; ++j) {
    const double y = grid_origin_mm_.y() + grid_step_mm_ * j;
    crossings.clear();
    for (size_t k = 0, previous = n - 1; k < n; previous = k++) {
      const Eigen::Vector2d& a = polygon_[previous];
      const Eigen::Vector2d& b = polygon_[k];
      if ((a.y() > y) != (b.y() > y)) crossings.push_back(a.x() + (y - a.y()) / (b.y() - a.y()) * (b.x() - a.x()));
    }
    std::sort(crossings.begin(), crossings.end());
    for (size_t c = 0; c + 1 < crossings.size(); c += 2) {
      const int i0 = std::max(0, static_cast<int>(std::ceil((crossings[c] - grid_origin_mm_.x()) / grid_step_mm_)));
      const int i1 = std::min(grid_nx_ - 1, static_cast<int>(std::floor((crossings[c + 1] - grid_origin_mm_.x()) / grid_step_mm_)));
      for (int i = i0; i <= i1; ++i) grid_distance_mm_[static_cast<size_t>(j) * grid_nx_ + i] *= -1.0f;
    }
  }
}

double PlanOutline::signed_distance_mm(double x_mm, double y_mm) const {
  const double gx = (x_mm - grid_origin_mm_.x()) / grid_step_mm_;
  const double gy = (y_mm - grid_origin_mm_.y()) / grid_step_mm_;
  const double cx = std::clamp(gx, 0.0, grid_nx_ - 1.000001);
  const double cy = std::clamp(gy, 0.0, grid_ny_ - 1.000001);
  const double outside_grid_mm = std::hypot(gx - cx, gy - cy) * grid_step_mm_;
  const int i = static_cast<int>(cx), j = static_cast<int>(cy);
  const double u = cx - i, v = cy - j;
  auto at = [this](int a, int b) { return static_cast<double>(grid_distance_mm_[static_cast<size_t>(b) * grid_nx_ + a]); };
  const double value = (1 - u) * (1 - v) * at(i, j) + u * (1 - v) * at(i + 1, j) + (1 - u) * v * at(i, j + 1) +
                       u * v * at(i + 1, j + 1);
  return value + outside_grid_mm;
}

Eigen::Vector2d PlanOutline::y_span_mm(double x_mm) const {
  const double index = std::clamp(x_mm, 0.0, static_cast<double>(y_span_by_mm_.size() - 1));
  const size_t i = std::min(static_cast<size_t>(index), y_span_by_mm_.size() - 2);
  const double t = index - static_cast<double>(i);
  return (1 - t) * y_span_by_mm_[i] + t * y_span_by_mm_[i + 1];
}

}  // namespace lastcut
