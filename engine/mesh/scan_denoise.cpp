#include "engine/mesh/scan_denoise.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lastcut {
namespace {

using Index = std::size_t;

std::vector<char> boundary_flags(const MeshTopology& topology) {
  std::vector<char> on_boundary(static_cast<Index>(topology.vertex_count()), 0);
  for (const auto& loop : topology.boundary_loops)
    for (const int v : loop) on_boundary[static_cast<Index>(v)] = 1;
  return on_boundary;
}

double mean_edge_mm(const TriMesh& mesh) {
  double sum = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) sum += (mesh.V.row(mesh.F(f, k)) - mesh.V.row(mesh.F(f, (k + 1) % 3))).norm();
  return mesh.F.rows() > 0 ? sum / (3.0 * static_cast<double>(mesh.F.rows())) : 0.0;
}

}  // namespace

double estimated_noise_mm(const TriMesh& mesh, const MeshTopology& topology) {
  const Eigen::MatrixXd normals = vertex_normals(mesh);
  const Index count = static_cast<Index>(mesh.V.rows());
  // A boundary vertex's umbrella is one-sided: its height measures the rim's curve, not noise.
  const std::vector<char> on_boundary = boundary_flags(topology);
  // Umbrella height: how far v sits above the centroid of its 1-ring, along its normal.
  std::vector<double> height(count, 0.0);
  for (Index v = 0; v < count; ++v) {
    const int begin = topology.neighbor_offsets[v], end = topology.neighbor_offsets[v + 1];
    if (end == begin || normals.row(static_cast<Eigen::Index>(v)).norm() == 0.0) continue;
    Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
    for (int i = begin; i < end; ++i) centroid += mesh.V.row(topology.neighbors[static_cast<Index>(i)]);
    centroid /= end - begin;
    height[v] = (mesh.V.row(static_cast<Eigen::Index>(v)) - centroid).dot(normals.row(static_cast<Eigen::Index>(v)));
  }
  std::vector<double> jumps;
  jumps.reserve(count);
  for (Index v = 0; v < count; ++v) {
    const int begin = topology.neighbor_offsets[v], end = topology.neighbor_offsets[v + 1];
    if (end == begin || on_boundary[v]) continue;
    double neighbours = 0;
    bool near_rim = false;
    for (int i = begin; i < end; ++i) {
      const Index w = static_cast<Index>(topology.neighbors[static_cast<Index>(i)]);
      neighbours += height[w];
      near_rim = near_rim || on_boundary[w];
    }
    if (near_rim) continue;
    jumps.push_back(std::abs(height[v] - neighbours / (end - begin)));
  }
  if (jumps.empty()) return 0.0;
  std::nth_element(jumps.begin(), jumps.begin() + static_cast<std::ptrdiff_t>(jumps.size() / 2), jumps.end());
  return jumps[jumps.size() / 2];
}

DenoiseReport denoise_scan(TriMesh& mesh, const MeshTopology& topology, const DenoiseOptions& options) {
  DenoiseReport report;
  report.noise_before_mm = report.noise_after_mm = estimated_noise_mm(mesh, topology);
  if (!(report.noise_before_mm > options.min_noise_mm)) return report;
  const std::vector<char> fixed = boundary_flags(topology);
  const double longest_tangential_mm = 0.25 * mean_edge_mm(mesh);
  // Taubin's pair: a smoothing step (lambda > 0) and an inflating one (mu < -lambda) make a
  // low-pass filter that takes the noise off without the shrinking of plain Laplacian smoothing.
  constexpr double kLambda = 0.5, kMu = -0.53;
  for (int pass = 0; pass < options.passes; ++pass) {
    for (const double factor : {kLambda, kMu}) {
      const Eigen::MatrixXd normals = vertex_normals(mesh);
      Eigen::MatrixXd moved = mesh.V;
      for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
        const int begin = topology.neighbor_offsets[static_cast<Index>(v)];
        const int end = topology.neighbor_offsets[static_cast<Index>(v) + 1];
        if (fixed[static_cast<Index>(v)] || end == begin || normals.row(v).norm() == 0.0) continue;
        const Eigen::RowVector3d normal = normals.row(v);  // unit
        Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
        for (int i = begin; i < end; ++i) centroid += mesh.V.row(topology.neighbors[static_cast<Index>(i)]);
        const Eigen::RowVector3d towards = centroid / (end - begin) - mesh.V.row(v);
        const double height = towards.dot(normal);
        moved.row(v) += factor * height * normal;
        if (factor < 0) continue;
        // Tangential relaxation (with the smoothing step only): a scanner's point error also
        // moves vertices along the surface, which folds thin triangles without changing the
        // shape; half a step towards the 1-ring's centroid in the tangent plane unfolds them.
        Eigen::RowVector3d along = 0.5 * (towards - height * normal);
        if (along.norm() > longest_tangential_mm) along *= longest_tangential_mm / along.norm();
        moved.row(v) += along;
      }
      mesh.V = std::move(moved);
    }
    ++report.passes;
  }
  report.noise_after_mm = estimated_noise_mm(mesh, topology);
  return report;
}

}  // namespace lastcut
