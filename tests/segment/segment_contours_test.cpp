// Where the feather line and the top rim run (engine/segment/contour_fields.hpp): by the shape of
// the last, so scanner noise and triangle density do not move them, and at the height and depth
// the options ask for.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <iostream>
#include <numbers>
#include <random>

#include "engine/lastgen/generate_last.hpp"
#include "engine/orient/orient_last.hpp"
#include "engine/segment/segment_last.hpp"
#include "segment_test_support.hpp"

namespace lastcut {
namespace {

OrientedLast clean_last(int triangles, LastSurface surface = LastParams{}.surface) {
  LastParams params = LastParams::for_eu_size(41, FootSide::Right);
  params.target_triangles = triangles;
  params.surface = surface;
  params.seed = 41;
  return orient_last(generate_last(params).mesh);
}

// The same surface with 0.2 mm Gaussian noise along the vertex normals, in the same frame.
OrientedLast with_noise(const OrientedLast& last, double sigma_mm) {
  OrientedLast noisy = last;
  Eigen::MatrixXd normals = Eigen::MatrixXd::Zero(last.mesh.V.rows(), 3);
  const Eigen::MatrixXd face_normals = triangle_normals(last.mesh);
  for (Eigen::Index f = 0; f < last.mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) normals.row(last.mesh.F(f, k)) += face_normals.row(f);
  normals.rowwise().normalize();
  std::mt19937_64 random(7);
  std::normal_distribution<double> noise(0.0, sigma_mm);
  for (Eigen::Index v = 0; v < last.mesh.V.rows(); ++v) noisy.mesh.V.row(v) += noise(random) * normals.row(v);
  return noisy;
}

double distance_to_polyline(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& loop) {
  double nearest = 1e300;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector3d a = loop[i], d = loop[(i + 1) % loop.size()] - a;
    const double t = std::clamp((p - a).dot(d) / std::max(d.squaredNorm(), 1e-12), 0.0, 1.0);
    nearest = std::min(nearest, (a + t * d - p).norm());
  }
  return nearest;
}

struct CurveGap {
  double max_mm = 0.0, mean_mm = 0.0;  // symmetric Hausdorff distance, and the mean over the points of both
};

CurveGap curve_gap(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  CurveGap gap;
  for (const auto* from : {&a, &b})
    for (const auto& p : *from) {
      const double d = distance_to_polyline(p, from == &a ? b : a);
      gap.max_mm = std::max(gap.max_mm, d);
      gap.mean_mm += d / static_cast<double>(a.size() + b.size());
    }
  return gap;
}

TEST(SegmentContours, NoiseAndDensityDoNotMoveTheCurves) {
  const OrientedLast last = clean_last(12000);
  const Segmentation clean = segment_last(last);
  const Segmentation noisy = segment_last(with_noise(last, 0.2));
  OrientedLast finer = last;
  finer.mesh = test::midpoint_subdivided(last.mesh, 1);  // the same flat facets, 4x the triangles
  const Segmentation dense = segment_last(finer);
  const CurveGap noise_lower = curve_gap(clean.lower_contour, noisy.lower_contour);
  const CurveGap noise_upper = curve_gap(clean.upper_contour, noisy.upper_contour);
  const CurveGap dense_lower = curve_gap(clean.lower_contour, dense.lower_contour);
  const CurveGap dense_upper = curve_gap(clean.upper_contour, dense.upper_contour);
  std::cout << "0.2 mm noise moves the feather line " << noise_lower.mean_mm << " mm on average, at most " << noise_lower.max_mm
            << " mm; the top rim " << noise_upper.mean_mm << ", " << noise_upper.max_mm << " mm\n"
            << "4x the triangles: feather line " << dense_lower.mean_mm << ", " << dense_lower.max_mm << " mm; top rim "
            << dense_upper.mean_mm << ", " << dense_upper.max_mm << " mm\n";
  // Bounds with some room above the figures of the geometric fields (docs/benchmarks-segment.md).
  for (const CurveGap* gap : {&noise_lower, &noise_upper, &dense_lower, &dense_upper}) EXPECT_LT(gap->mean_mm, 0.35);
  EXPECT_LT(noise_lower.max_mm, 1.2);
  EXPECT_LT(noise_upper.max_mm, 0.7);
  EXPECT_LT(dense_lower.max_mm, 0.9);
  EXPECT_LT(dense_upper.max_mm, 0.9);
}

// The plane of the flat top cut of a clean scan: least squares through the corners of the faces
// that face up within 3 degrees near the top. Returns {point, upward unit normal}.
std::pair<Eigen::Vector3d, Eigen::Vector3d> top_cut_plane(const TriMesh& mesh) {
  const Eigen::VectorXd elevation = test::face_elevation_rad(mesh);
  const double top_z = mesh.V.col(2).maxCoeff();
  std::vector<Eigen::Vector3d> points;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    if (elevation(f) > 87.0 * std::numbers::pi / 180.0 && mesh.V(mesh.F(f, 0), 2) > top_z - 10.0)
      for (int k = 0; k < 3; ++k) points.emplace_back(mesh.V.row(mesh.F(f, k)).transpose());
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& p : points) centre += p;
  centre /= static_cast<double>(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& p : points) scatter += (p - centre) * (p - centre).transpose();
  Eigen::Vector3d normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvectors().col(0);
  if (normal.z() < 0.0) normal = -normal;
  return {centre, normal};
}

// The rim at the asked depth on both kinds of top cut: rounded (the remeshed last's 2 mm fillet: a ramp
// of the field, averaged across the rim) and sharp (the Bezier last's crease, whose first vertex row lies
// about 3 mm down: the cap kept apart, the side's height unclamped; segment_last.cpp).
class TopRimDepth : public testing::TestWithParam<LastSurface> {};

TEST_P(TopRimDepth, RunsTheAskedDepthBelowTheTopCut) {
  const OrientedLast last = clean_last(12000, GetParam());
  const auto [point, normal] = top_cut_plane(last.mesh);
  for (double depth_mm : {1.25, 2.5}) {
    SegmentOptions options;
    options.rim_depth_mm = depth_mm;
    const Segmentation result = segment_last(last, options);
    double shallowest = 1e300, deepest = -1e300;
    for (const auto& p : result.upper_contour) {
      const double depth = (point - p).dot(normal);
      shallowest = std::min(shallowest, depth);
      deepest = std::max(deepest, depth);
    }
    std::cout << "rim depth " << depth_mm << " mm: contour " << shallowest << " .. " << deepest << " mm below the cut\n";
    // The moving average against noise (segment_last.cpp) shifts the curve a little where the
    // wall meets the cut at a shallow angle.
    EXPECT_NEAR(shallowest, depth_mm, 0.5);
    EXPECT_NEAR(deepest, depth_mm, 0.5);
  }
}

INSTANTIATE_TEST_SUITE_P(Surfaces, TopRimDepth, testing::Values(LastSurface::Remeshed, LastSurface::Bezier),
                         [](const testing::TestParamInfo<LastSurface>& param_info) {
                           return param_info.param == LastSurface::Bezier ? std::string("sharp") : std::string("rounded");
                         });

}  // namespace
}  // namespace lastcut
