#include "engine/segment/region_contour.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/edge_path.hpp"
#include "engine/core/engine_error.hpp"

namespace lastcut {

std::vector<int> region_boundary_loop(const TriMesh& mesh, const MeshTopology& topology, const std::vector<char>& region) {
  auto in_region = [&region](int face) { return face >= 0 && region[static_cast<std::size_t>(face)]; };
  // A contour edge has a region face on one side only (or no face on the other side).
  auto on_contour = [&](int a, int b) {
    const int ab = topology.find_half_edge(a, b), ba = topology.find_half_edge(b, a);
    const bool left = ab >= 0 && in_region(ab / 3), right = ba >= 0 && in_region(ba / 3);
    return left != right;
  };
  int cut_from = -1, cut_to = -1;
  double cut_x = std::numeric_limits<double>::infinity();
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    if (!region[static_cast<std::size_t>(f)]) continue;
    for (int k = 0; k < 3; ++k) {
      if (in_region(topology.face_across(f, k))) continue;
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      const double x = 0.5 * (mesh.V(a, 0) + mesh.V(b, 0));
      if (x < cut_x) { cut_x = x; cut_from = a; cut_to = b; }
    }
  }
  if (cut_from < 0) throw EngineError("a surface region has no boundary: the mesh is not a closed last");

  // The shortest way round along the contour, without the edge between cut_from and cut_to.
  const EdgePath path = shortest_edge_path(mesh, topology, cut_from, cut_to, [&](int u, int w) {
    return !((u == cut_from && w == cut_to) || (u == cut_to && w == cut_from)) && on_contour(u, w);
  });
  if (path.vertices.empty()) throw EngineError("the contour around a surface region is not closed");
  return path.vertices;
}

namespace {

// The closed loop resampled at equal arc-length steps (the step count is rounded so the steps
// close the loop exactly).
std::vector<Eigen::Vector3d> resample_closed(const std::vector<Eigen::Vector3d>& points, double spacing_mm) {
  const std::size_t n = points.size();
  std::vector<double> along(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) along[i + 1] = along[i] + (points[(i + 1) % n] - points[i]).norm();
  const double length = along[n];
  const auto count = static_cast<std::size_t>(std::max(3.0, std::round(length / spacing_mm)));
  std::vector<Eigen::Vector3d> samples;
  samples.reserve(count);
  std::size_t edge = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double s = length * static_cast<double>(k) / static_cast<double>(count);
    while (edge + 1 < n && along[edge + 1] <= s) ++edge;
    const double l = along[edge + 1] - along[edge];
    const double u = l > 0.0 ? (s - along[edge]) / l : 0.0;
    samples.push_back(points[edge] + u * (points[(edge + 1) % n] - points[edge]));
  }
  return samples;
}

}  // namespace

std::vector<Eigen::Vector3d> smooth_closed_polyline(const std::vector<Eigen::Vector3d>& input, int passes,
                                                    double spacing_mm) {
  if (input.size() < 3) return input;
  if (!(spacing_mm > 0.0)) throw EngineError("the contour resampling step must be positive");
  std::vector<Eigen::Vector3d> points = resample_closed(input, spacing_mm);
  const std::size_t n = points.size();
  std::vector<Eigen::Vector3d> next(n);
  for (int pass = 0; pass < passes; ++pass) {
    for (std::size_t i = 0; i < n; ++i)
      next[i] = 0.5 * points[i] + 0.25 * (points[(i + n - 1) % n] + points[(i + 1) % n]);
    points.swap(next);
  }
  return points;
}

}  // namespace lastcut
