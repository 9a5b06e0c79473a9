// Convex-combination embedding on an ellipse; see tutte_embedding.hpp.
#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/tutte_embedding.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lastcut {
namespace {

// cot(89.4 deg) / 2: the smallest half-edge weight of the start map (any positive value keeps it flip-free).
constexpr double kMinimumHalfWeight = 0.01;

// Ramanujan's approximation of the perimeter of an ellipse with semi-axes a, b.
double ellipse_perimeter(double a, double b) {
  return std::numbers::pi * (3.0 * (a + b) - std::sqrt((3.0 * a + b) * (a + 3.0 * b)));
}

}  // namespace

Eigen::MatrixXd boundary_on_ellipse(const TriMesh& mesh, const std::vector<int>& loop, double area_mm2) {
  const int count = static_cast<int>(loop.size());
  // Cumulative boundary length; index positions of the diameter's end points in the loop.
  std::vector<double> arc(count + 1, 0.0);
  for (int i = 0; i < count; ++i) {
    arc[i + 1] = arc[i] + (mesh.V.row(loop[(i + 1) % count]) - mesh.V.row(loop[i])).norm();
  }
  const double perimeter = arc[count];
  const int end_a = farthest_vertex_on_loop(mesh, loop, loop[0]);
  const int end_b = farthest_vertex_on_loop(mesh, loop, end_a);
  const int ia = static_cast<int>(std::find(loop.begin(), loop.end(), end_a) - loop.begin());
  int ib = static_cast<int>(std::find(loop.begin(), loop.end(), end_b) - loop.begin());
  if (ib == ia) ib = (ia + count / 2) % count;

  // Semi-axes: perimeter matches the boundary length, a*b*pi matches the area (a circle if the surface
  // has more area than a flat disk of that perimeter could hold).
  double a = perimeter / (2.0 * std::numbers::pi), b = a;
  if (area_mm2 < perimeter * perimeter / (4.0 * std::numbers::pi)) {
    double lo = std::sqrt(area_mm2 / std::numbers::pi), hi = perimeter / 2.0;
    for (int it = 0; it < 80; ++it) {
      const double mid = 0.5 * (lo + hi);
      (ellipse_perimeter(mid, area_mm2 / (std::numbers::pi * mid)) < perimeter ? lo : hi) = mid;
    }
    a = lo;
    b = std::max(area_mm2 / (std::numbers::pi * a), 0.02 * a);
  }

  // Walk counter-clockwise from end A (angle pi) to end B (angle 2 pi) and back to A (angle 3 pi),
  // each half by arc length: strictly increasing angles keep the polygon strictly convex.
  Eigen::MatrixXd positions(count, 2);
  const auto arc_from_a = [&](int i) {
    const double s = arc[i] - arc[ia];
    return s < 0 ? s + perimeter : s;
  };
  const double split = arc_from_a(ib);
  for (int i = 0; i < count; ++i) {
    const double s = arc_from_a(i);
    const double angle = s <= split ? std::numbers::pi * (1.0 + s / split)
                                    : std::numbers::pi * (2.0 + (s - split) / (perimeter - split));
    positions(i, 0) = a * std::cos(angle);
    positions(i, 1) = b * std::sin(angle);
  }
  return positions;
}

Eigen::MatrixXd tutte_embedding(const TriMesh& mesh, const TriangleFrames& frames, const MeshTopology& topology,
                                ReducedLaplacian& laplacian, SparseCholesky& solver) {
  const int vertex_count = mesh.vertex_count();
  Eigen::MatrixXd UV = Eigen::MatrixXd::Zero(vertex_count, 2);
  std::vector<char> fixed(vertex_count, 0);
  const Eigen::MatrixXd ring = boundary_on_ellipse(mesh, topology.boundary_loops[0], frames.area_mm2.sum());
  for (size_t i = 0; i < topology.boundary_loops[0].size(); ++i) {
    UV.row(topology.boundary_loops[0][i]) = ring.row(static_cast<Eigen::Index>(i));
    fixed[topology.boundary_loops[0][i]] = 1;
  }

  // Positive weights: clamp the cotangent weights from below (obtuse angles give zero or negative ones).
  std::vector<double> weight(frames.half_weight.size());
  std::transform(frames.half_weight.begin(), frames.half_weight.end(), weight.begin(),
                 [](double w) { return std::max(w, kMinimumHalfWeight); });
  assemble_laplacian(frames, weight, fixed, laplacian);

  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(laplacian.matrix.rows(), 2);
  for (size_t f = 0; f < frames.triangles.size(); ++f) {
    const auto& t = frames.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      const double w = weight[3 * f + k];
      if (fixed[a] && !fixed[b]) rhs.row(laplacian.row_of_vertex[b]) += w * UV.row(a);
      if (fixed[b] && !fixed[a]) rhs.row(laplacian.row_of_vertex[a]) += w * UV.row(b);
    }
  }
  for (int v : topology.boundary_loops[0]) {
    if (laplacian.row_of_vertex[v] >= 0) rhs.row(laplacian.row_of_vertex[v]) = UV.row(v);
  }
  solver.factorize(laplacian.matrix);
  const Eigen::MatrixXd solution = solver.solve(rhs);
  for (size_t r = 0; r < laplacian.vertex_of_row.size(); ++r) {
    const int v = laplacian.vertex_of_row[r];
    if (!fixed[v]) UV.row(v) = solution.row(static_cast<Eigen::Index>(r));
  }
  return UV;
}

}  // namespace lastcut
