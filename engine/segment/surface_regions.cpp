#include "engine/segment/surface_regions.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

constexpr double kSolePieceShare = 0.02;  // a low down-facing piece this share of the sole's area joins it
constexpr double kSoleBridgeMm = 12.0;     // closing radius that joins such pieces to the sole

int largest_component(const std::vector<int>& component, int count, const Eigen::VectorXd& areas) {
  const std::vector<double> sums = component_areas(component, count, areas);
  return static_cast<int>(std::max_element(sums.begin(), sums.end()) - sums.begin());
}

double mean_edge_length_mm(const TriMesh& mesh) {
  double sum = 0.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) sum += (mesh.V.row(mesh.F(f, k)) - mesh.V.row(mesh.F(f, (k + 1) % 3))).norm();
  return mesh.F.rows() > 0 ? sum / (3.0 * static_cast<double>(mesh.F.rows())) : 0.0;
}

Eigen::Vector3d face_centroid(const TriMesh& mesh, Eigen::Index f) {
  return (mesh.V.row(mesh.F(f, 0)) + mesh.V.row(mesh.F(f, 1)) + mesh.V.row(mesh.F(f, 2))).transpose() / 3.0;
}

// Faces reachable from seed through faces that pass `accept`.
template <typename Accept>
std::vector<char> grow_from(const MeshTopology& topology, int seed, Accept accept) {
  std::vector<char> region(static_cast<std::size_t>(topology.face_count()), 0);
  std::vector<int> stack{seed};
  region[static_cast<std::size_t>(seed)] = 1;
  while (!stack.empty()) {
    const int f = stack.back();
    stack.pop_back();
    for (int k = 0; k < 3; ++k) {
      const int g = topology.face_across(f, k);
      if (g < 0 || region[static_cast<std::size_t>(g)] || !accept(g)) continue;
      region[static_cast<std::size_t>(g)] = 1;
      stack.push_back(g);
    }
  }
  return region;
}

// Morphological closing over faces sharing a vertex: `rings` dilations, then `rings` erosions
// that never remove a face of the original region. Bridges gaps up to about 2 x rings edges.
void close_region(const TriMesh& mesh, std::vector<char>& region, int rings) {
  const std::vector<char> original = region;
  std::vector<char> touched(static_cast<std::size_t>(mesh.V.rows()));
  for (int grow = 0; grow < 2 * rings; ++grow) {
    const bool dilating = grow < rings;
    std::fill(touched.begin(), touched.end(), 0);
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
      if (static_cast<bool>(region[static_cast<std::size_t>(f)]) == dilating)
        for (int k = 0; k < 3; ++k) touched[static_cast<std::size_t>(mesh.F(f, k))] = 1;
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
      const bool near = touched[static_cast<std::size_t>(mesh.F(f, 0))] || touched[static_cast<std::size_t>(mesh.F(f, 1))] ||
                        touched[static_cast<std::size_t>(mesh.F(f, 2))];
      auto& in = region[static_cast<std::size_t>(f)];
      if (dilating && near) in = 1;
      if (!dilating && near && !original[static_cast<std::size_t>(f)]) in = 0;
    }
  }
}

}  // namespace

Eigen::VectorXd smoothed_elevation_rad(const TriMesh& mesh, const MeshTopology& topology, double passes) {
  const Eigen::Index vertex_count = mesh.V.rows();
  Eigen::MatrixXd normals = Eigen::MatrixXd::Zero(vertex_count, 3);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const Eigen::RowVector3d area_normal = 0.5 * (b - a).cross(c - a).transpose();  // length = area
    for (int k = 0; k < 3; ++k) normals.row(mesh.F(f, k)) += area_normal;
  }
  Eigen::MatrixXd next(vertex_count, 3);
  // A mesh without edges (empty: the caller refuses it later with its reason) gives no edge length
  // and so a NaN or infinite count: no smoothing then, rather than a cast of NaN to int (UB).
  if (!std::isfinite(passes) || passes < 0) passes = 0;
  // A fractional last pass adds only that share of the neighbours, so the smoothing radius in mm
  // can follow the edge length continuously.
  for (int pass = 0; pass < static_cast<int>(std::ceil(passes)); ++pass) {
    const double share = std::min(1.0, passes - pass);
    for (Eigen::Index v = 0; v < vertex_count; ++v) {
      Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
      for (int i = topology.neighbor_offsets[static_cast<std::size_t>(v)]; i < topology.neighbor_offsets[static_cast<std::size_t>(v) + 1]; ++i)
        sum += normals.row(topology.neighbors[static_cast<std::size_t>(i)]);
      next.row(v) = normals.row(v) + share * sum;
    }
    normals.swap(next);
    normals.rowwise().normalize();
  }
  Eigen::VectorXd elevation(mesh.F.rows());
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d n = (normals.row(mesh.F(f, 0)) + normals.row(mesh.F(f, 1)) + normals.row(mesh.F(f, 2))).transpose();
    const double length = n.norm();
    elevation(f) = length > 0.0 ? std::asin(std::clamp(n.z() / length, -1.0, 1.0)) : 0.0;
  }
  return elevation;
}

void fill_region_gaps(const MeshTopology& topology, const Eigen::VectorXd& areas, std::vector<char>& region) {
  std::vector<char> outside(region.size());
  for (std::size_t f = 0; f < region.size(); ++f) outside[f] = !region[f];
  int count = 0;
  const std::vector<int> component = face_components(topology, outside, count);
  if (count <= 1) return;
  const int keep = largest_component(component, count, areas);
  for (std::size_t f = 0; f < region.size(); ++f)
    if (component[f] >= 0 && component[f] != keep) region[f] = 1;
}

std::vector<char> sole_region(const TriMesh& mesh, const MeshTopology& topology, const Eigen::VectorXd& elevation_rad,
                              const Eigen::VectorXd& areas, double sole_angle_rad) {
  std::vector<char> facing_down(static_cast<std::size_t>(elevation_rad.size()));
  for (Eigen::Index f = 0; f < elevation_rad.size(); ++f) facing_down[static_cast<std::size_t>(f)] = elevation_rad(f) <= sole_angle_rad;
  int count = 0;
  const std::vector<int> component = face_components(topology, facing_down, count);
  if (count == 0) throw EngineError("no triangle faces down: the last is not standing on its sole");
  const std::vector<double> sums = component_areas(component, count, areas);
  const int largest = static_cast<int>(std::max_element(sums.begin(), sums.end()) - sums.begin());

  // Besides the largest piece, low pieces of some size belong to the sole too (a foot scan's toe
  // pads, cut off from the ball by the toe crease); they are joined to it by a closing.
  const double z_min = mesh.V.col(2).minCoeff(), low_limit = z_min + (mesh.V.col(2).maxCoeff() - z_min) / 3.0;
  std::vector<double> weighted_z(static_cast<std::size_t>(count), 0.0);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const int c = component[static_cast<std::size_t>(f)];
    if (c >= 0) weighted_z[static_cast<std::size_t>(c)] += areas(f) * face_centroid(mesh, f).z();
  }
  std::vector<char> keep(static_cast<std::size_t>(count), 0);
  int kept = 0;
  for (int c = 0; c < count; ++c) {
    const auto i = static_cast<std::size_t>(c);
    keep[i] = c == largest || (sums[i] >= kSolePieceShare * sums[static_cast<std::size_t>(largest)] &&
                               weighted_z[i] / sums[i] < low_limit);
    kept += keep[i] ? 1 : 0;
  }
  std::vector<char> region(facing_down.size(), 0);
  for (std::size_t f = 0; f < region.size(); ++f) region[f] = component[f] >= 0 && keep[static_cast<std::size_t>(component[f])];
  if (kept > 1) {
    const int rings = std::clamp(static_cast<int>(std::ceil(kSoleBridgeMm / mean_edge_length_mm(mesh))), 1, 12);
    close_region(mesh, region, rings);
    int pieces = 0;
    const std::vector<int> joined = face_components(topology, region, pieces);
    const std::vector<double> piece_areas = component_areas(joined, pieces, areas);
    const int main_piece = static_cast<int>(std::max_element(piece_areas.begin(), piece_areas.end()) - piece_areas.begin());
    for (std::size_t f = 0; f < region.size(); ++f) region[f] = joined[f] == main_piece;
  }
  fill_region_gaps(topology, areas, region);
  return region;
}

std::vector<char> top_region(const TriMesh& mesh, const MeshTopology& topology, const Eigen::VectorXd& elevation_rad,
                             const Eigen::VectorXd& areas, double top_angle_rad) {
  int seed = -1;
  double seed_height = -1e300;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    if (elevation_rad(f) < top_angle_rad) continue;
    const double height = face_centroid(mesh, f).z();
    if (height > seed_height) { seed_height = height; seed = static_cast<int>(f); }
  }
  if (seed < 0) throw EngineError("no triangle faces up: the last has no top cut");

  // The cut is flat: a face belongs to it when it faces up and lies close to the plane of the
  // faces found so far. Two rounds let the plane settle away from the rounded rim near the seed.
  const double tolerance_mm = std::max(2.0, 1.5 * mean_edge_length_mm(mesh));
  const Eigen::MatrixXd face_normals = triangle_normals(mesh);
  std::vector<char> region = grow_from(topology, seed, [&](int f) { return elevation_rad(f) >= top_angle_rad; });
  for (int round = 0; round < 2; ++round) {
    Eigen::Vector3d point = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
    double weight = 0.0;
    for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
      if (!region[static_cast<std::size_t>(f)]) continue;
      point += areas(f) * face_centroid(mesh, f);
      normal += areas(f) * face_normals.row(f).transpose();
      weight += areas(f);
    }
    point /= weight;
    normal.normalize();
    region = grow_from(topology, seed, [&](int f) {
      return elevation_rad(f) >= top_angle_rad && std::abs((face_centroid(mesh, f) - point).dot(normal)) <= tolerance_mm;
    });
  }
  fill_region_gaps(topology, areas, region);
  return region;
}

}  // namespace lastcut
