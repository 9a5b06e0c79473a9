#include "engine/mesh/marching_tetrahedra.hpp"

#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

// Parity of a permutation of {0,1,2,3}: +1 even, -1 odd.
int permutation_parity(const std::array<int, 4>& order) {
  int inversions = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (order[i] > order[j]) ++inversions;
  return inversions % 2 == 0 ? 1 : -1;
}

struct KuhnTet {
  std::array<Eigen::Vector3i, 4> corner_offsets;
  int orientation;  // sign of det(v1 - v0, v2 - v0, v3 - v0)
};

std::array<KuhnTet, 6> kuhn_tets() {
  const std::array<std::array<int, 3>, 6> axis_orders{{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  std::array<KuhnTet, 6> tets;
  for (size_t t = 0; t < 6; ++t) {
    Eigen::Vector3i corner = Eigen::Vector3i::Zero();
    tets[t].corner_offsets[0] = corner;
    for (int step = 0; step < 3; ++step) {
      corner(axis_orders[t][step]) += 1;
      tets[t].corner_offsets[step + 1] = corner;
    }
    const std::array<int, 4> as_permutation{0, axis_orders[t][0] + 1, axis_orders[t][1] + 1, axis_orders[t][2] + 1};
    tets[t].orientation = permutation_parity(as_permutation);
  }
  return tets;
}

class SurfaceBuilder {
 public:
  SurfaceBuilder(const SampleGrid& grid, const std::vector<double>& values) : grid_(grid), values_(values) {}

  int64_t node_index(const Eigen::Vector3i& ijk) const {
    return (static_cast<int64_t>(ijk.z()) * grid_.node_count.y() + ijk.y()) * grid_.node_count.x() + ijk.x();
  }

  // The vertex where the surface crosses the grid segment between two nodes of opposite sign.
  int crossing_vertex(int64_t a, int64_t b, const Eigen::Vector3i& ijk_a, const Eigen::Vector3i& ijk_b) {
    if (a > b) return crossing_vertex(b, a, ijk_b, ijk_a);
    const int64_t key = a * (grid_.node_count.prod() + 1) + b;
    const auto found = vertex_of_segment_.find(key);
    if (found != vertex_of_segment_.end()) return found->second;
    const double fa = values_[static_cast<size_t>(a)];
    const double fb = values_[static_cast<size_t>(b)];
    const double t = fa / (fa - fb);
    const Eigen::Vector3d pa = grid_.origin_mm + grid_.spacing_mm * ijk_a.cast<double>();
    const Eigen::Vector3d pb = grid_.origin_mm + grid_.spacing_mm * ijk_b.cast<double>();
    const int index = static_cast<int>(vertices_.size());
    vertices_.push_back(pa + t * (pb - pa));
    vertex_of_segment_.emplace(key, index);
    return index;
  }

  void add_triangle(int a, int b, int c) { faces_.push_back({a, b, c}); }

  TriMesh take() {
    TriMesh mesh;
    mesh.V.resize(static_cast<Eigen::Index>(vertices_.size()), 3);
    for (size_t v = 0; v < vertices_.size(); ++v) mesh.V.row(static_cast<Eigen::Index>(v)) = vertices_[v].transpose();
    mesh.F.resize(static_cast<Eigen::Index>(faces_.size()), 3);
    for (size_t f = 0; f < faces_.size(); ++f)
      mesh.F.row(static_cast<Eigen::Index>(f)) << faces_[f][0], faces_[f][1], faces_[f][2];
    return mesh;
  }

 private:
  const SampleGrid& grid_;
  const std::vector<double>& values_;
  std::unordered_map<int64_t, int> vertex_of_segment_;
  std::vector<Eigen::Vector3d> vertices_;
  std::vector<std::array<int, 3>> faces_;
};

}  // namespace

TriMesh marching_tetrahedra(const SampleGrid& grid, const std::function<double(const Eigen::Vector3d&)>& field) {
  const Eigen::Vector3i n = grid.node_count;
  if (n.minCoeff() < 2 || !(grid.spacing_mm > 0.0)) throw EngineError("marching tetrahedra: empty sample grid");
  std::vector<double> values(static_cast<size_t>(n.prod()));
  for (int k = 0; k < n.z(); ++k)
    for (int j = 0; j < n.y(); ++j)
      for (int i = 0; i < n.x(); ++i) {
        const Eigen::Vector3d p = grid.origin_mm + grid.spacing_mm * Eigen::Vector3d(i, j, k);
        double value = field(p);
        if (value == 0.0) value = 1e-12;  // no vertex exactly on the surface: every crossing is strict
        const bool on_boundary = i == 0 || j == 0 || k == 0 || i == n.x() - 1 || j == n.y() - 1 || k == n.z() - 1;
        if (on_boundary && value < 0.0) throw EngineError("marching tetrahedra: the surface leaves the sample grid");
        values[static_cast<size_t>((static_cast<int64_t>(k) * n.y() + j) * n.x() + i)] = value;
      }

  const std::array<KuhnTet, 6> tets = kuhn_tets();
  SurfaceBuilder builder(grid, values);
  for (int k = 0; k + 1 < n.z(); ++k)
    for (int j = 0; j + 1 < n.y(); ++j)
      for (int i = 0; i + 1 < n.x(); ++i) {
        const Eigen::Vector3i base(i, j, k);
        for (const KuhnTet& tet : tets) {
          std::array<Eigen::Vector3i, 4> ijk;
          std::array<int64_t, 4> node;
          std::array<int, 4> inside_list{}, outside_list{};
          int inside = 0, outside = 0;
          for (int c = 0; c < 4; ++c) {
            ijk[c] = base + tet.corner_offsets[c];
            node[c] = builder.node_index(ijk[c]);
            if (values[static_cast<size_t>(node[c])] < 0.0)
              inside_list[inside++] = c;
            else
              outside_list[outside++] = c;
          }
          if (inside == 0 || outside == 0) continue;
          auto cross = [&](int a, int b) { return builder.crossing_vertex(node[a], node[b], ijk[a], ijk[b]); };
          if (inside == 1 || outside == 1) {
            // One corner alone on its side: one triangle on the three segments leaving it, facing
            // away from it when it is inside (see the orientation derivation for a unit tetrahedron).
            const int lone = inside == 1 ? inside_list[0] : outside_list[0];
            std::array<int, 3> others = inside == 1 ? std::array<int, 3>{outside_list[0], outside_list[1], outside_list[2]}
                                                    : std::array<int, 3>{inside_list[0], inside_list[1], inside_list[2]};
            int sign = tet.orientation * permutation_parity({lone, others[0], others[1], others[2]});
            if (inside != 1) sign = -sign;
            if (sign < 0) std::swap(others[1], others[2]);
            builder.add_triangle(cross(lone, others[0]), cross(lone, others[1]), cross(lone, others[2]));
          } else {
            // Two and two: a quad, split in two triangles, facing the outside pair.
            int i0 = inside_list[0], i1 = inside_list[1];
            const int o0 = outside_list[0], o1 = outside_list[1];
            if (tet.orientation * permutation_parity({i0, i1, o0, o1}) < 0) std::swap(i0, i1);
            const int a = cross(i0, o0), b = cross(i0, o1), c = cross(i1, o1), d = cross(i1, o0);
            builder.add_triangle(a, b, c);
            builder.add_triangle(a, c, d);
          }
        }
      }
  return builder.take();
}

}  // namespace lastcut
