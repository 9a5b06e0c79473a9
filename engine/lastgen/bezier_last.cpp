#include "engine/lastgen/bezier_last.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <unordered_map>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/lastgen/cube_sphere.hpp"
#include "engine/lastgen/last_side_mesh.hpp"
#include "engine/subdiv/sample_surface.hpp"

namespace lastcut {
namespace {

constexpr int kTypicalControlQuads = 1500;  // n grows once the control mesh has this many quads
constexpr int kCellSearch = 3;              // box sides tried around the proportional ones
constexpr int kCapSmoothingSteps = 50;

// Box cells with 4 n^2 (nx ny + nx nz + ny nz) triangles as close to the target from below as
// possible; ties go to the box nearest the proportional one.
std::array<int, 3> cells_for_count(const Eigen::Vector3d& extent_mm, int n, int target_triangles) {
  const int per_unit = 4 * n * n;
  const std::array<int, 3> base = cube_cells_for(extent_mm, std::max(24, target_triangles / (2 * n * n)));
  std::array<int, 3> best = base;
  long long best_gap = std::numeric_limits<long long>::max();
  int best_distance = 0;
  for (int dx = -kCellSearch; dx <= kCellSearch; ++dx) {
    for (int dy = -kCellSearch; dy <= kCellSearch; ++dy) {
      for (int dz = -kCellSearch; dz <= kCellSearch; ++dz) {
        const int x = base[0] + dx, y = base[1] + dy, z = base[2] + dz;
        if (x < 2 || y < 2 || z < 2) continue;
        const long long gap = target_triangles - static_cast<long long>(per_unit) * (x * y + x * z + y * z);
        const int distance = std::abs(dx) + std::abs(dy) + std::abs(dz);
        if (gap < 0 || gap > best_gap || (gap == best_gap && distance >= best_distance)) continue;
        best = {x, y, z}, best_gap = gap, best_distance = distance;
      }
    }
  }
  return best;
}

// The side's boundary as one loop of output vertices, following its half-edges from `start`.
std::vector<int> boundary_loop(const QuadMesh& quads, int start) {
  const auto key = [&quads](int a, int b) { return static_cast<long long>(a) * quads.vertex_count() + b; };
  std::unordered_map<long long, int> half_edges;
  half_edges.reserve(static_cast<size_t>(4 * quads.quad_count()));
  for (Eigen::Index q = 0; q < quads.Q.rows(); ++q) {
    for (int k = 0; k < 4; ++k) half_edges.emplace(key(quads.Q(q, k), quads.Q(q, (k + 1) % 4)), 0);
  }
  std::vector<int> next(static_cast<size_t>(quads.vertex_count()), -1);
  for (Eigen::Index q = 0; q < quads.Q.rows(); ++q) {
    for (int k = 0; k < 4; ++k) {
      const int a = quads.Q(q, k), b = quads.Q(q, (k + 1) % 4);
      if (!half_edges.contains(key(b, a))) next[static_cast<size_t>(a)] = b;
    }
  }
  std::vector<int> loop{start};
  for (int v = next[static_cast<size_t>(start)]; v != start; v = next[static_cast<size_t>(v)]) {
    if (v < 0 || loop.size() > next.size()) throw EngineError("Bezier last: the side surface's rim is not one loop");
    loop.push_back(v);
  }
  return loop;
}

}  // namespace

int bezier_detail_for(int target_triangles) {
  const double n = std::floor(std::sqrt(target_triangles / (2.0 * kTypicalControlQuads)));
  return static_cast<int>(std::clamp(n, 1.0, 8.0));
}

TriMesh bezier_last_surface(const LastShape& shape, const LastParams& params) {
  const int n = bezier_detail_for(params.target_triangles);
  const auto [low, high] = shape.bounds_mm();
  const LastSideMesh side = last_side_mesh(shape, params, cells_for_count(high - low, n, params.target_triangles));
  const QuadMesh quads = subdivide_bezier(side.control, n, SampleSpread::EvenAtExtraordinary).quads;

  // Output vertex v < #control V is the limit point of control vertex v (all of them are used).
  const std::vector<int> loop = boundary_loop(quads, side.cap_corners[0]);
  const int nu = n * side.cap_cells_u, nv = n * side.cap_cells_v;
  const auto loop_size = static_cast<size_t>(2 * (nu + nv));
  if (loop.size() != loop_size || loop[static_cast<size_t>(nu)] != side.cap_corners[1] ||
      loop[static_cast<size_t>(nu + nv)] != side.cap_corners[2] || loop[static_cast<size_t>(2 * nu + nv)] != side.cap_corners[3]) {
    throw EngineError("Bezier last: the rim does not match the cap's cells");
  }

  // The cap grid g(i, j), i = 0..nu, j = 0..nv: rim samples on its border, new vertices inside.
  const int side_vertices = quads.vertex_count();
  std::vector<int> grid(static_cast<size_t>((nu + 1) * (nv + 1)));
  const auto g = [&grid, nu](int i, int j) -> int& { return grid[static_cast<size_t>(i + (nu + 1) * j)]; };
  int next_id = side_vertices;
  for (int j = 0; j <= nv; ++j) {
    for (int i = 0; i <= nu; ++i) {
      if (j == 0) {
        g(i, j) = loop[static_cast<size_t>(i)];
      } else if (i == nu) {
        g(i, j) = loop[static_cast<size_t>(nu + j)];
      } else if (j == nv) {
        g(i, j) = loop[static_cast<size_t>(2 * nu + nv - i)];
      } else if (i == 0) {
        g(i, j) = loop[(loop_size - static_cast<size_t>(j)) % loop_size];
      } else {
        g(i, j) = next_id++;
      }
    }
  }
  Eigen::MatrixXd V(next_id, 3);
  V.topRows(side_vertices) = quads.V;
  const auto at = [&V](int id) -> Eigen::Vector3d { return V.row(id).transpose(); };
  for (int j = 1; j < nv; ++j) {
    for (int i = 1; i < nu; ++i) {
      const double u = static_cast<double>(i) / nu, v = static_cast<double>(j) / nv;
      const Eigen::Vector3d coons = (1 - v) * at(g(i, 0)) + v * at(g(i, nv)) + (1 - u) * at(g(0, j)) + u * at(g(nu, j)) -
                                    ((1 - u) * (1 - v) * at(g(0, 0)) + u * (1 - v) * at(g(nu, 0)) +
                                     (1 - u) * v * at(g(0, nv)) + u * v * at(g(nu, nv)));
      V.row(g(i, j)) = coons.transpose();
    }
  }
  for (int step = 0; step < kCapSmoothingSteps; ++step) {
    const Eigen::MatrixXd previous = V;
    for (int j = 1; j < nv; ++j) {
      for (int i = 1; i < nu; ++i) {
        V.row(g(i, j)) = 0.25 * (previous.row(g(i - 1, j)) + previous.row(g(i + 1, j)) + previous.row(g(i, j - 1)) +
                                 previous.row(g(i, j + 1)));
      }
    }
  }
  const auto into_cut = [&side](const Eigen::Vector3d& p) -> Eigen::Vector3d {
    return p - (p - side.cut_point_mm).dot(side.cut_normal) * side.cut_normal;
  };
  for (Eigen::Index v = side_vertices; v < V.rows(); ++v) V.row(v) = into_cut(V.row(v).transpose()).transpose();

  // Cap quads run against the side's boundary (the loop follows the side's half-edges).
  const int cap_quads = nu * nv;
  const long long missing = static_cast<long long>(params.target_triangles) - 2LL * (quads.quad_count() + cap_quads);
  const long long splits = std::max(0LL, missing / 2);
  if (splits > cap_quads) throw EngineError("Bezier last: the triangle count is too far from the control mesh's");
  std::vector<char> split(static_cast<size_t>(cap_quads), 0);
  for (long long s = 0; s < splits; ++s) split[static_cast<size_t>((2 * s + 1) * cap_quads / (2 * splits))] = 1;

  QuadMesh whole;
  whole.Q.resize(quads.quad_count() + cap_quads - splits, 4);
  whole.Q.topRows(quads.quad_count()) = quads.Q;
  std::vector<Eigen::Vector4i> split_quads;
  Eigen::Index row = quads.quad_count();
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const Eigen::Vector4i quad(g(i, j), g(i, j + 1), g(i + 1, j + 1), g(i + 1, j));
      if (split[static_cast<size_t>(i + nu * j)] != 0) {
        split_quads.push_back(quad);
      } else {
        whole.Q.row(row++) = quad.transpose();
      }
    }
  }
  whole.V = V;
  TriMesh mesh = triangulate_quads(whole);
  const Eigen::Index first_centre = mesh.V.rows(), first_face = mesh.F.rows();
  mesh.V.conservativeResize(first_centre + static_cast<Eigen::Index>(split_quads.size()), 3);
  mesh.F.conservativeResize(first_face + 4 * static_cast<Eigen::Index>(split_quads.size()), 3);
  for (size_t s = 0; s < split_quads.size(); ++s) {
    const Eigen::Vector4i& quad = split_quads[s];
    const Eigen::Vector3d centre = 0.25 * (at(quad(0)) + at(quad(1)) + at(quad(2)) + at(quad(3)));
    const auto c = static_cast<int>(first_centre + static_cast<Eigen::Index>(s));
    mesh.V.row(c) = into_cut(centre).transpose();
    for (int k = 0; k < 4; ++k) mesh.F.row(first_face + 4 * static_cast<Eigen::Index>(s) + k) << quad(k), quad((k + 1) % 4), c;
  }
  return mesh;
}

}  // namespace lastcut
