// Isometric triangle frames, cotangent weights and pattern-reusing Laplacian assembly; see cotangent_laplacian.hpp.
#include "engine/flatten/cotangent_laplacian.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/engine_error.hpp"

namespace lastcut {

TriangleFrames compute_triangle_frames(const TriMesh& mesh) {
  const int face_count = mesh.triangle_count();
  TriangleFrames frames;
  frames.triangles.resize(face_count);
  frames.half_weight.resize(3 * static_cast<size_t>(face_count));
  frames.edge_local_mm.resize(6 * static_cast<size_t>(face_count));
  frames.area_mm2.resize(face_count);
  for (int f = 0; f < face_count; ++f) {
    const std::array<int, 3> t{mesh.F(f, 0), mesh.F(f, 1), mesh.F(f, 2)};
    frames.triangles[f] = t;
    const Eigen::Vector3d p0 = mesh.V.row(t[0]), p1 = mesh.V.row(t[1]), p2 = mesh.V.row(t[2]);
    const Eigen::Vector3d e01 = p1 - p0, e02 = p2 - p0, e12 = p2 - p1;
    const double twice_area = e01.cross(e02).norm();
    const double longest_sq = std::max({e01.squaredNorm(), e02.squaredNorm(), e12.squaredNorm()});
    if (!(twice_area > 1e-12 * longest_sq)) {
      throw EngineError("triangle " + std::to_string(f) + " has zero area: repair the mesh before flattening");
    }
    frames.area_mm2(f) = 0.5 * twice_area;
    double* w = &frames.half_weight[3 * static_cast<size_t>(f)];
    w[0] = 0.5 * e01.dot(e02) / twice_area;
    w[1] = 0.5 * (-e01).dot(e12) / twice_area;
    w[2] = 0.5 * e02.dot(e12) / twice_area;
    // Frame: v0 at the origin, v1 on +x, v2 above the x axis (counter-clockwise, like the 3D face).
    const double l01 = e01.norm();
    const Eigen::Vector2d x0(0.0, 0.0), x1(l01, 0.0), x2(e02.dot(e01) / l01, twice_area / l01);
    const Eigen::Vector2d edges[3] = {x2 - x1, x0 - x2, x1 - x0};
    double* e = &frames.edge_local_mm[6 * static_cast<size_t>(f)];
    for (int k = 0; k < 3; ++k) {
      e[2 * k] = edges[k].x();
      e[2 * k + 1] = edges[k].y();
    }
  }
  return frames;
}

ReducedLaplacian build_reduced_pattern(const TriangleFrames& frames, const MeshTopology& topology, int pinned) {
  const int vertex_count = static_cast<int>(topology.neighbor_offsets.size()) - 1;
  ReducedLaplacian lap;
  lap.pinned = pinned;
  lap.row_of_vertex.assign(vertex_count, -1);
  for (int v = 0, row = 0; v < vertex_count; ++v) {
    if (v == pinned) continue;
    lap.row_of_vertex[v] = row++;
    lap.vertex_of_row.push_back(v);
  }
  const int n = vertex_count - 1;
  // Column c holds rows of its vertex and its neighbours, ascending (row order follows vertex order).
  std::vector<int> outer(n + 1, 0);
  std::vector<int> inner;
  inner.reserve(topology.neighbors.size() + n);
  for (int c = 0; c < n; ++c) {
    const int v = lap.vertex_of_row[c];
    bool diagonal_written = false;
    for (int i = topology.neighbor_offsets[v]; i < topology.neighbor_offsets[v + 1]; ++i) {
      const int r = lap.row_of_vertex[topology.neighbors[i]];
      if (r < 0) continue;
      if (!diagonal_written && r > c) {
        inner.push_back(c);
        diagonal_written = true;
      }
      inner.push_back(r);
    }
    if (!diagonal_written) inner.push_back(c);
    outer[c + 1] = static_cast<int>(inner.size());
  }
  lap.matrix.resize(n, n);
  lap.matrix.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), lap.matrix.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), lap.matrix.innerIndexPtr());
  std::fill_n(lap.matrix.valuePtr(), inner.size(), 0.0);

  auto slot_of = [&](int row, int col) {
    if (row < 0 || col < 0) return -1;
    const int* begin = inner.data() + outer[col];
    const int* end = inner.data() + outer[col + 1];
    return static_cast<int>(std::lower_bound(begin, end, row) - inner.data());
  };
  lap.slot.resize(9 * frames.triangles.size());
  for (size_t f = 0; f < frames.triangles.size(); ++f) {
    int* s = &lap.slot[9 * f];
    const auto& t = frames.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int r = lap.row_of_vertex[t[k]];
      s[k] = slot_of(r, r);
      const int a = lap.row_of_vertex[t[(k + 1) % 3]], b = lap.row_of_vertex[t[(k + 2) % 3]];
      s[3 + 2 * k] = slot_of(a, b);
      s[4 + 2 * k] = slot_of(b, a);
    }
  }
  return lap;
}

void assemble_laplacian(const TriangleFrames& frames, const std::vector<double>& half_weight,
                        const std::vector<char>& fixed, ReducedLaplacian& lap) {
  double* values = lap.matrix.valuePtr();
  std::fill_n(values, lap.matrix.nonZeros(), 0.0);
  for (size_t f = 0; f < frames.triangles.size(); ++f) {
    const int* s = &lap.slot[9 * f];
    const auto& t = frames.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const double w = half_weight[3 * f + k];
      const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      const int ka = (k + 1) % 3, kb = (k + 2) % 3;
      if (!fixed[a]) values[s[ka]] += w;
      if (!fixed[b]) values[s[kb]] += w;
      if (!fixed[a] && !fixed[b]) {
        values[s[3 + 2 * k]] -= w;
        values[s[4 + 2 * k]] -= w;
      }
    }
  }
  for (size_t r = 0; r < lap.vertex_of_row.size(); ++r) {
    if (fixed[lap.vertex_of_row[r]]) {
      const int c = static_cast<int>(r);
      const int* begin = lap.matrix.innerIndexPtr() + lap.matrix.outerIndexPtr()[c];
      const int* end = lap.matrix.innerIndexPtr() + lap.matrix.outerIndexPtr()[c + 1];
      values[std::lower_bound(begin, end, c) - lap.matrix.innerIndexPtr()] = 1.0;
    }
  }
}

ReducedLaplacian pinned_cotangent_laplacian(const TriangleFrames& frames, const MeshTopology& topology) {
  ReducedLaplacian laplacian = build_reduced_pattern(frames, topology, topology.boundary_loops[0].front());
  std::vector<char> fixed(laplacian.row_of_vertex.size(), 0);
  fixed[static_cast<size_t>(laplacian.pinned)] = 1;
  assemble_laplacian(frames, frames.half_weight, fixed, laplacian);
  return laplacian;
}

}  // namespace lastcut
