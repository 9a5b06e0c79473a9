#include "engine/segment/segment_halves.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/engine_error.hpp"
#include "engine/segment/half_edge_index.hpp"
#include "engine/segment/surface_regions.hpp"

namespace lastcut {
namespace {

struct BoundaryShape {
  int loops = 0;
  bool pinched = false;
  long long euler_characteristic = 0;  // V - E + F
  std::vector<int> vertices;           // every boundary vertex
};

// Boundary loops and Euler characteristic: a half-edge without a twin is on the boundary, and
// E = (half-edges + boundary half-edges) / 2 on a manifold.
BoundaryShape boundary_shape(const TriMesh& mesh) {
  const HalfEdgeIndex index = build_half_edge_index(mesh.F, mesh.V.rows());
  BoundaryShape shape;
  std::vector<int> next(static_cast<std::size_t>(mesh.V.rows()), -1);
  for (std::size_t from = 0; from + 1 < index.offsets.size(); ++from)
    for (int i = index.offsets[from]; i < index.offsets[from + 1]; ++i) {
      const int to = index.target[static_cast<std::size_t>(i)];
      if (index.find(static_cast<int>(from), to) != i) shape.pinched = true;  // the same edge twice
      if (index.find(to, static_cast<int>(from)) >= 0) continue;
      if (next[from] >= 0) shape.pinched = true;
      next[from] = to;
      shape.vertices.push_back(static_cast<int>(from));
    }
  std::vector<char> visited(next.size(), 0);
  for (int start : shape.vertices) {
    if (visited[static_cast<std::size_t>(start)]) continue;
    ++shape.loops;
    for (int v = start; v >= 0 && !visited[static_cast<std::size_t>(v)]; v = next[static_cast<std::size_t>(v)])
      visited[static_cast<std::size_t>(v)] = 1;
  }
  const auto edges = static_cast<long long>((index.target.size() + shape.vertices.size()) / 2);
  shape.euler_characteristic = static_cast<long long>(mesh.V.rows()) - edges + static_cast<long long>(mesh.F.rows());
  return shape;
}

}  // namespace

Segment extract_half(const TriMesh& cut, const MeshGraph& graph, const std::vector<int>& labels, int label,
                     const Eigen::MatrixXd& fields, const std::string& name) {
  const Eigen::VectorXd areas = triangle_areas(cut);
  std::vector<char> in_half(labels.size());
  for (std::size_t f = 0; f < labels.size(); ++f) in_half[f] = labels[f] == label;
  int count = 0;
  const std::vector<int> component = face_components(graph, in_half, count);
  if (count == 0) throw EngineError("the " + name + " half is empty: the split plane misses the last");
  const std::vector<double> sums = component_areas(component, count, areas);
  const int keep = static_cast<int>(std::max_element(sums.begin(), sums.end()) - sums.begin());
  for (std::size_t f = 0; f < labels.size(); ++f) in_half[f] = component[f] == keep;
  fill_region_gaps(graph, areas, in_half);

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

  const BoundaryShape shape = boundary_shape(segment.mesh);
  const long long euler = shape.euler_characteristic;
  if (shape.loops != 1 || shape.pinched || euler != 1)
    throw EngineError("the " + name + " half is not a single sheet (" + std::to_string(shape.loops) +
                      " boundary loops, Euler characteristic " + std::to_string(euler) +
                      "): the scan has a hole or a fold on that side");

  // Corners: boundary vertices lying on the plane cut and on the feather line or the top rim.
  constexpr double kOnPlaneMm = 1e-6, kOnContour = 1e-9;
  auto corner_pair = [&](int contour_field, const char* front_name, const char* back_name) {
    int front = -1, back = -1;
    for (int v : shape.vertices) {
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
