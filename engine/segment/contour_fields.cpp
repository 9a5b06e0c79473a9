#include "engine/segment/contour_fields.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <utility>

namespace lastcut {
namespace {

constexpr double kSoleKnotSpacingMm = 15.0;  // B-spline knots along the last (at most this far apart)
constexpr double kSolePenalty = 0.01;         // second-difference penalty, relative to the fitted area
constexpr int kSoleDegreeY = 2;      // crown across the sole
constexpr int kSoleMixedDegreeX = 2; // how the crown changes along the last
constexpr double kMinInlierShare = 0.5;
constexpr int kMaxSoleIntervals = 64;        // bounds the solve for an object far larger than a last

// Each vertex's share of the area of its faces that belong to `region` (mm^2), #V.
Eigen::VectorXd region_vertex_weights(const TriMesh& mesh, const std::vector<char>& region, const Eigen::VectorXd& areas) {
  Eigen::VectorXd weight = Eigen::VectorXd::Zero(mesh.V.rows());
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    if (region[static_cast<std::size_t>(f)])
      for (int k = 0; k < 3; ++k) weight(mesh.F(f, k)) += areas(f) / 3.0;
  return weight;
}

// Keeps field > 0 only on the vertices connected through positive vertices to a vertex of the
// region; other positive vertices (a far part of the surface that happens to come close to the
// fitted shape) are set to -1 mm. Their neighbours outside the kept set are all <= 0 already, so
// the level set around the kept set does not move.
void keep_connected_to_region(const MeshTopology& topology, const Eigen::VectorXd& region_weight, Eigen::VectorXd& field) {
  const auto vertex_count = static_cast<std::size_t>(field.size());
  std::vector<char> kept(vertex_count, 0);
  std::vector<int> stack;
  for (std::size_t v = 0; v < vertex_count; ++v)
    if (region_weight(static_cast<Eigen::Index>(v)) > 0.0 && field(static_cast<Eigen::Index>(v)) > 0.0) {
      kept[v] = 1;
      stack.push_back(static_cast<int>(v));
    }
  while (!stack.empty()) {
    const auto v = static_cast<std::size_t>(stack.back());
    stack.pop_back();
    for (int i = topology.neighbor_offsets[v]; i < topology.neighbor_offsets[v + 1]; ++i) {
      const auto w = static_cast<std::size_t>(topology.neighbors[static_cast<std::size_t>(i)]);
      if (kept[w] || !(field(static_cast<Eigen::Index>(w)) > 0.0)) continue;
      kept[w] = 1;
      stack.push_back(static_cast<int>(w));
    }
  }
  for (std::size_t v = 0; v < vertex_count; ++v)
    if (!kept[v] && field(static_cast<Eigen::Index>(v)) > 0.0) field(static_cast<Eigen::Index>(v)) = -1.0;
}

struct PlaneFit {
  Eigen::Vector3d point, normal;
};

PlaneFit fit_plane(const TriMesh& mesh, const Eigen::VectorXd& weight) {
  const double total = weight.sum();
  const Eigen::Vector3d point = (mesh.V.transpose() * weight) / total;
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    if (weight(v) > 0.0) {
      const Eigen::Vector3d d = mesh.V.row(v).transpose() - point;
      scatter += weight(v) * d * d.transpose();
    }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  Eigen::Vector3d normal = solver.eigenvectors().col(0);  // smallest spread: across the plane
  if (normal.z() < 0.0) normal = -normal;
  return {point, normal};
}

// Weighted RMS of residuals over the vertices with weight > 0.
double weighted_rms(const Eigen::VectorXd& residual, const Eigen::VectorXd& weight) {
  const double total = weight.sum();
  return total > 0.0 ? std::sqrt(weight.dot(residual.cwiseAbs2()) / total) : 0.0;
}

// Drops (weight 0) the vertices whose residual is beyond `limit`.
Eigen::VectorXd inliers(const Eigen::VectorXd& weight, const Eigen::VectorXd& residual, double limit) {
  return (residual.array().abs() <= limit).select(weight, 0.0);
}

// z ~ s(x, y) = sum_k c_k B_k(x) + crown terms: uniform cubic B-splines along the last (local, so
// the toe spring does not bend the fit at the heel as one polynomial would, and extended linearly
// past the ends instead of swinging away), plus polynomial terms in y for the crown across.
struct SoleBasis {
  double x0 = 0.0, knot_spacing_mm = 1.0;
  int intervals = 1;
  Eigen::Vector2d centre, scale;
  int spline_count() const { return intervals + 3; }
  int size() const { return spline_count() + kSoleDegreeY * (kSoleMixedDegreeX + 1); }

  Eigen::VectorXd operator()(double x, double y) const {
    Eigen::VectorXd row = Eigen::VectorXd::Zero(size());
    const double s = std::clamp((x - x0) / knot_spacing_mm, -1e6, 1e6);  // keeps floor() within int
    const int i = std::clamp(static_cast<int>(std::floor(s)), 0, intervals - 1);
    const double t = std::clamp(s - i, 0.0, 1.0), beyond = s - i - t;  // beyond: past an end, in knot spacings
    const double value[4] = {std::pow(1.0 - t, 3) / 6.0, (3.0 * t * t * t - 6.0 * t * t + 4.0) / 6.0,
                             (-3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0) / 6.0, t * t * t / 6.0};
    const double slope[4] = {-0.5 * (1.0 - t) * (1.0 - t), 0.5 * (3.0 * t * t - 4.0 * t), 0.5 * (-3.0 * t * t + 2.0 * t + 1.0),
                             0.5 * t * t};
    for (int k = 0; k < 4; ++k) row(i + k) = value[k] + beyond * slope[k];
    const double u = (x - centre.x()) / scale.x(), w = (y - centre.y()) / scale.y();
    int k = spline_count();
    for (int j = 1; j <= kSoleDegreeY; ++j)
      for (int m = 0; m <= kSoleMixedDegreeX; ++m) row(k++) = std::pow(u, m) * std::pow(w, j);
    return row;
  }
};

// Weighted least squares z ~ basis(x, y) . c over the vertices with weight > 0, with a penalty on
// the second differences of the spline coefficients (a P-spline: Eilers & Marx, "Flexible
// smoothing with B-splines and penalties", Statistical Science 11(2), 1996) so that a stretch with
// few points (a scan hole, the narrow toe) is bridged smoothly.
Eigen::VectorXd fit_height(const TriMesh& mesh, const SoleBasis& basis, const Eigen::VectorXd& weight) {
  const int n = basis.size();
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
    if (!(weight(v) > 0.0)) continue;
    const Eigen::VectorXd row = basis(mesh.V(v, 0), mesh.V(v, 1));
    normal.selfadjointView<Eigen::Lower>().rankUpdate(row, weight(v));
    rhs += weight(v) * mesh.V(v, 2) * row;
  }
  normal = normal.selfadjointView<Eigen::Lower>();
  const double penalty = kSolePenalty * weight.sum() / basis.spline_count();
  for (int k = 1; k + 1 < basis.spline_count(); ++k) {
    const int index[3] = {k - 1, k, k + 1};
    const double coefficient[3] = {1.0, -2.0, 1.0};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) normal(index[a], index[b]) += penalty * coefficient[a] * coefficient[b];
  }
  normal.diagonal().array() += 1e-9 * std::max(1.0, normal.diagonal().maxCoeff());
  return normal.ldlt().solve(rhs);
}

}  // namespace

Eigen::VectorXd smooth_vertex_field(const TriMesh& mesh, const Eigen::VectorXd& areas, Eigen::VectorXd values,
                                    double passes) {
  return smooth_vertex_field(mesh, areas, std::move(values), passes, std::vector<char>(static_cast<size_t>(mesh.F.rows()), 0));
}

Eigen::VectorXd smooth_vertex_field(const TriMesh& mesh, const Eigen::VectorXd& areas, Eigen::VectorXd values, double passes,
                                    const std::vector<char>& plane_faces) {
  const Eigen::Index vertex_count = mesh.V.rows();
  // A vertex of a plane face averages over its plane faces only.
  std::vector<char> on_plane(static_cast<size_t>(vertex_count), 0);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    if (plane_faces[static_cast<size_t>(f)])
      for (int k = 0; k < 3; ++k) on_plane[static_cast<size_t>(mesh.F(f, k))] = 1;
  const auto counts = [&](Eigen::Index f, int k) { return plane_faces[static_cast<size_t>(f)] || !on_plane[static_cast<size_t>(mesh.F(f, k))]; };
  Eigen::VectorXd total = Eigen::VectorXd::Zero(vertex_count);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (counts(f, k)) total(mesh.F(f, k)) += areas(f);
  Eigen::VectorXd next(vertex_count);
  for (int pass = 0; pass < static_cast<int>(std::ceil(passes)); ++pass) {
    const double share = std::min(1.0, passes - pass);
    next.setZero();
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
      const double mean = (values(mesh.F(f, 0)) + values(mesh.F(f, 1)) + values(mesh.F(f, 2))) / 3.0;
      for (int k = 0; k < 3; ++k)
        if (counts(f, k)) next(mesh.F(f, k)) += areas(f) * mean;
    }
    for (Eigen::Index v = 0; v < vertex_count; ++v)
      if (total(v) > 0.0) values(v) += share * (next(v) / total(v) - values(v));
  }
  return values;
}

std::optional<ContourField> top_plane_field(const TriMesh& mesh, const MeshTopology& topology, const std::vector<char>& top,
                                               const Eigen::VectorXd& areas, double depth_mm, double max_rms_mm) {
  const Eigen::VectorXd region_weight = region_vertex_weights(mesh, top, areas);
  if (!((region_weight.array() > 0.0).count() >= 3)) return std::nullopt;
  // The region reaches into the rounded rim; refit on the vertices near the plane so the rim does
  // not tilt or lower it.
  PlaneFit plane = fit_plane(mesh, region_weight);
  Eigen::VectorXd weight = region_weight;
  for (double limit_mm : {1.0, 0.5}) {
    const Eigen::VectorXd height = (mesh.V.rowwise() - plane.point.transpose()) * plane.normal;
    weight = inliers(region_weight, height, limit_mm);
    if (weight.sum() < kMinInlierShare * region_weight.sum()) return std::nullopt;
    plane = fit_plane(mesh, weight);
  }
  const Eigen::VectorXd height = (mesh.V.rowwise() - plane.point.transpose()) * plane.normal;
  const double rms_mm = weighted_rms(height, weight);
  if (rms_mm > max_rms_mm) return std::nullopt;
  Eigen::VectorXd field = height.array() + depth_mm;
  keep_connected_to_region(topology, region_weight, field);
  return ContourField{std::move(field), rms_mm};
}

std::optional<ContourField> sole_height_field(const TriMesh& mesh, const MeshTopology& topology,
                                                 const std::vector<char>& sole, const Eigen::VectorXd& areas,
                                                 double height_mm, double max_rms_mm) {
  const Eigen::VectorXd region_weight = region_vertex_weights(mesh, sole, areas);
  SoleBasis basis;
  Eigen::Vector2d low(1e300, 1e300), high(-1e300, -1e300);
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    if (region_weight(v) > 0.0) {
      low = low.cwiseMin(mesh.V.row(v).head<2>().transpose());
      high = high.cwiseMax(mesh.V.row(v).head<2>().transpose());
    }
  if (!(high.x() > low.x() && high.y() > low.y())) return std::nullopt;
  basis.centre = 0.5 * (low + high);
  basis.scale = 0.5 * (high - low);
  basis.x0 = low.x();
  basis.intervals = std::clamp(static_cast<int>(std::ceil((high.x() - low.x()) / kSoleKnotSpacingMm)), 1, kMaxSoleIntervals);
  basis.knot_spacing_mm = (high.x() - low.x()) / basis.intervals;
  // Residuals on the sole only while refitting (the rest is not used until the end).
  auto residual_of = [&](const Eigen::VectorXd& coefficients, bool everywhere) {
    Eigen::VectorXd residual = Eigen::VectorXd::Zero(mesh.V.rows());
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
      if (everywhere || region_weight(v) > 0.0) residual(v) = mesh.V(v, 2) - basis(mesh.V(v, 0), mesh.V(v, 1)).dot(coefficients);
    return residual;
  };
  // The region reaches up into the feather edge's rounding; each refit keeps the points near the
  // surface fitted so far, so the fit settles on the sole itself.
  Eigen::VectorXd coefficients = fit_height(mesh, basis, region_weight);
  Eigen::VectorXd weight = region_weight;
  for (double limit_mm : {2.0, 1.0, 0.6}) {
    weight = inliers(region_weight, residual_of(coefficients, false), limit_mm);
    if (weight.sum() < kMinInlierShare * region_weight.sum()) return std::nullopt;
    coefficients = fit_height(mesh, basis, weight);
  }
  const Eigen::VectorXd residual = residual_of(coefficients, true);
  const double rms_mm = weighted_rms(residual, weight);
  if (rms_mm > max_rms_mm) return std::nullopt;
  Eigen::VectorXd field = height_mm - residual.array();
  keep_connected_to_region(topology, region_weight, field);
  return ContourField{std::move(field), rms_mm};
}

}  // namespace lastcut
