#include "engine/mesh/scan_denoise.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace lastcut {
namespace {

using Index = std::size_t;

Eigen::MatrixXd face_area_normals(const TriMesh& mesh) {
  Eigen::MatrixXd normals(mesh.F.rows(), 3);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    normals.row(f) = 0.5 * (b - a).cross(c - a).transpose();  // length = area
  }
  return normals;
}

// Per vertex: the sum of the area normals of its faces (an unnormalised vertex normal).
Eigen::MatrixXd vertex_area_normals(const TriMesh& mesh, const Eigen::MatrixXd& face_normals) {
  Eigen::MatrixXd normals = Eigen::MatrixXd::Zero(mesh.V.rows(), 3);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) normals.row(mesh.F(f, k)) += face_normals.row(f);
  return normals;
}

std::vector<char> boundary_flags(const MeshTopology& topology) {
  std::vector<char> on_boundary(static_cast<Index>(topology.vertex_count()), 0);
  for (const auto& loop : topology.boundary_loops)
    for (const int v : loop) on_boundary[static_cast<Index>(v)] = 1;
  return on_boundary;
}

// Every vertex's 2-ring without itself (sorted, no repeats), in compressed rows: built once,
// used by every pass.
struct Rings {
  std::vector<int> offsets;  // #V + 1
  std::vector<int> members;
};

Rings two_rings(const MeshTopology& t) {
  Rings rings;
  const int count = t.vertex_count();
  rings.offsets.reserve(static_cast<Index>(count) + 1);
  rings.offsets.push_back(0);
  std::vector<int> ring;
  for (int v = 0; v < count; ++v) {
    ring.clear();
    for (int i = t.neighbor_offsets[static_cast<Index>(v)]; i < t.neighbor_offsets[static_cast<Index>(v) + 1]; ++i) {
      const int w = t.neighbors[static_cast<Index>(i)];
      ring.push_back(w);
      for (int j = t.neighbor_offsets[static_cast<Index>(w)]; j < t.neighbor_offsets[static_cast<Index>(w) + 1]; ++j)
        if (t.neighbors[static_cast<Index>(j)] != v) ring.push_back(t.neighbors[static_cast<Index>(j)]);
    }
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    rings.members.insert(rings.members.end(), ring.begin(), ring.end());
    rings.offsets.push_back(static_cast<int>(rings.members.size()));
  }
  return rings;
}

double mean_edge_mm(const TriMesh& mesh) {
  double sum = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) sum += (mesh.V.row(mesh.F(f, k)) - mesh.V.row(mesh.F(f, (k + 1) % 3))).norm();
  return mesh.F.rows() > 0 ? sum / (3.0 * static_cast<double>(mesh.F.rows())) : 0.0;
}

}  // namespace

double estimated_noise_mm(const TriMesh& mesh, const MeshTopology& topology) {
  const Eigen::MatrixXd normals = vertex_area_normals(mesh, face_area_normals(mesh));
  const Index count = static_cast<Index>(mesh.V.rows());
  // Umbrella height: how far v sits above the centroid of its 1-ring, along its normal.
  std::vector<double> height(count, 0.0);
  for (Index v = 0; v < count; ++v) {
    const int begin = topology.neighbor_offsets[v], end = topology.neighbor_offsets[v + 1];
    if (end == begin || normals.row(static_cast<Eigen::Index>(v)).norm() == 0.0) continue;
    Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
    for (int i = begin; i < end; ++i) centroid += mesh.V.row(topology.neighbors[static_cast<Index>(i)]);
    centroid /= end - begin;
    height[v] = (mesh.V.row(static_cast<Eigen::Index>(v)) - centroid).dot(normals.row(static_cast<Eigen::Index>(v)).normalized());
  }
  std::vector<double> jumps;
  jumps.reserve(count);
  for (Index v = 0; v < count; ++v) {
    const int begin = topology.neighbor_offsets[v], end = topology.neighbor_offsets[v + 1];
    if (end == begin) continue;
    double neighbours = 0;
    for (int i = begin; i < end; ++i) neighbours += height[static_cast<Index>(topology.neighbors[static_cast<Index>(i)])];
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
  const double sigma_c = mean_edge_mm(mesh);
  const Rings rings = two_rings(topology);
  // Closeness weights from the scan as read: a pass moves vertices by the noise, a small part of
  // sigma_c, so the weights hardly change and half of the exponentials are saved.
  std::vector<double> closeness(rings.members.size());
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    for (int i = rings.offsets[static_cast<Index>(v)]; i < rings.offsets[static_cast<Index>(v) + 1]; ++i) {
      const double t = (mesh.V.row(rings.members[static_cast<Index>(i)]) - mesh.V.row(v)).norm();
      closeness[static_cast<Index>(i)] = std::exp(-t * t / (2 * sigma_c * sigma_c));
    }
  std::vector<double> heights;
  for (int pass = 0; pass < options.passes; ++pass) {
    const Eigen::MatrixXd vertex_normals = vertex_area_normals(mesh, face_area_normals(mesh));
    Eigen::MatrixXd moved = mesh.V;
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
      if (fixed[static_cast<Index>(v)]) continue;
      const std::span<const int> ring(rings.members.data() + rings.offsets[static_cast<Index>(v)],
                                      rings.members.data() + rings.offsets[static_cast<Index>(v) + 1]);
      Eigen::RowVector3d mollified = vertex_normals.row(v);
      for (const int w : ring) mollified += vertex_normals.row(w);
      if (ring.empty() || mollified.norm() == 0.0) continue;
      mollified.normalize();
      heights.clear();
      double mean = 0;
      for (const int w : ring) {
        heights.push_back((mesh.V.row(w) - mesh.V.row(v)).dot(mollified));
        mean += heights.back();
      }
      mean /= static_cast<double>(heights.size());
      double variance = 0;
      for (const double h : heights) variance += (h - mean) * (h - mean);
      const double sigma_s = std::max(std::sqrt(variance / static_cast<double>(heights.size())), 0.1 * sigma_c);
      double weighted = 0, weights = 0;
      const double* closeness_of_ring = closeness.data() + rings.offsets[static_cast<Index>(v)];
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const double h = heights[i];
        const double w = closeness_of_ring[i] * std::exp(-h * h / (2 * sigma_s * sigma_s));
        weighted += w * h;
        weights += w;
      }
      if (weights > 0) moved.row(v) += (weighted / weights) * mollified;
      // Tangential relaxation: a scanner's point error also moves vertices along the surface,
      // which folds thin triangles without changing the shape; half a step towards the 1-ring's
      // centroid, in the tangent plane only, unfolds them and leaves the surface where it is.
      const int begin = topology.neighbor_offsets[static_cast<Index>(v)], end = topology.neighbor_offsets[static_cast<Index>(v) + 1];
      Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
      for (int i = begin; i < end; ++i) centroid += mesh.V.row(topology.neighbors[static_cast<Index>(i)]);
      const Eigen::RowVector3d towards = centroid / (end - begin) - mesh.V.row(v);
      moved.row(v) += 0.5 * (towards - towards.dot(mollified) * mollified);
    }
    mesh.V = std::move(moved);
    ++report.passes;
  }
  report.noise_after_mm = estimated_noise_mm(mesh, topology);
  return report;
}

}  // namespace lastcut
