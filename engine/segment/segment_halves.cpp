#include "engine/segment/segment_halves.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/engine_error.hpp"
#include "engine/segment/surface_regions.hpp"

namespace lastcut {
namespace {

// Boundary vertices (those with a boundary half-edge leaving them), in increasing order.
std::vector<int> boundary_vertices(const MeshTopology& topology) {
  std::vector<int> vertices;
  for (int v = 0; v < topology.vertex_count(); ++v)
    for (int i = topology.out_offsets[static_cast<std::size_t>(v)]; i < topology.out_offsets[static_cast<std::size_t>(v) + 1]; ++i)
      if (topology.across[static_cast<std::size_t>(topology.out_half_edges[static_cast<std::size_t>(i)])] == kBoundaryEdge) {
        vertices.push_back(v);
        break;
      }
  return vertices;
}

// An edge used twice the same way or by more than two faces: the half folds onto itself.
bool has_folded_edge(const MeshTopology& topology) {
  for (std::size_t h = 0; h < topology.across.size(); ++h)
    if (topology.across[h] == kCrowdedEdge || topology.same_direction[h]) return true;
  return false;
}

}  // namespace

Segment extract_half(const TriMesh& cut, const MeshTopology& topology, const std::vector<int>& labels, int label,
                     const Eigen::MatrixXd& fields, const std::string& name) {
  const Eigen::VectorXd areas = triangle_areas(cut);
  std::vector<char> in_half(labels.size());
  for (std::size_t f = 0; f < labels.size(); ++f) in_half[f] = labels[f] == label;
  int count = 0;
  const std::vector<int> component = face_components(topology, in_half, count);
  if (count == 0) throw EngineError("the " + name + " half is empty: the split plane misses the last");
  const std::vector<double> sums = component_areas(component, count, areas);
  const int keep = static_cast<int>(std::max_element(sums.begin(), sums.end()) - sums.begin());
  for (std::size_t f = 0; f < labels.size(); ++f) in_half[f] = component[f] == keep;
  fill_region_gaps(topology, areas, in_half);

  Segment segment;
  segment.name = name;
  std::vector<int> new_index(static_cast<std::size_t>(cut.V.rows()), -1);
  std::vector<int> old_index;
  int face_total = 0;
  for (std::size_t f = 0; f < in_half.size(); ++f) face_total += in_half[f] ? 1 : 0;
  segment.mesh.F.resize(face_total, 3);
  int row = 0;
  for (std::size_t f = 0; f < in_half.size(); ++f) {
    if (!in_half[f]) continue;
    for (int k = 0; k < 3; ++k) {
      int& index = new_index[static_cast<std::size_t>(cut.F(static_cast<Eigen::Index>(f), k))];
      if (index < 0) {
        index = static_cast<int>(old_index.size());
        old_index.push_back(cut.F(static_cast<Eigen::Index>(f), k));
      }
      segment.mesh.F(row, k) = index;
    }
    ++row;
  }
  segment.mesh.V.resize(static_cast<Eigen::Index>(old_index.size()), 3);
  for (std::size_t v = 0; v < old_index.size(); ++v) segment.mesh.V.row(static_cast<Eigen::Index>(v)) = cut.V.row(old_index[v]);

  segment.topology = build_mesh_topology(segment.mesh.F, segment.mesh.V.rows());
  const MeshTopology& half = segment.topology;
  const auto loops = static_cast<int>(half.boundary_loops.size()) + half.open_boundary_chains;
  const long long euler = segment.mesh.V.rows() - half.edge_count() + segment.mesh.F.rows();
  if (loops != 1 || half.first_pinch_vertex >= 0 || has_folded_edge(half) || euler != 1)
    throw EngineError("the " + name + " half is not a single sheet (" + std::to_string(loops) +
                      " boundary loops, Euler characteristic " + std::to_string(euler) +
                      "): the scan has a hole or a fold on that side");

  // Corners: boundary vertices lying on the plane cut and on the feather line or the top rim.
  constexpr double kOnPlaneMm = 1e-6, kOnContour = 1e-9;
  auto corner_pair = [&](int contour_field, const char* front_name, const char* back_name) {
    int front = -1, back = -1;
    for (int v : boundary_vertices(half)) {
      const int old = old_index[static_cast<std::size_t>(v)];
      if (std::abs(fields(old, kPlaneField)) > kOnPlaneMm || std::abs(fields(old, contour_field)) > kOnContour) continue;
      if (front < 0 || segment.mesh.V(v, 0) > segment.mesh.V(front, 0)) front = v;
      if (back < 0 || segment.mesh.V(v, 0) < segment.mesh.V(back, 0)) back = v;
    }
    if (front < 0 || front == back)
      throw EngineError("the centre cut of the " + name + " half does not reach the " +
                        (contour_field == kSoleField ? "feather line" : "top rim") + " at both ends");
    segment.landmarks[front_name] = front;
    segment.landmarks[back_name] = back;
  };
  corner_pair(kSoleField, "toe", "heel");
  corner_pair(kTopField, "top_front", "top_back");
  return segment;
}

}  // namespace lastcut
