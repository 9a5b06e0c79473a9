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

// 4 sqrt(3) area / (sum of squared edges): 1 for an equilateral triangle, 0 for a degenerate one.
double triangle_quality(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const double edges = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  return edges > 0.0 ? 2.0 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / edges : 0.0;
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
  // Spread over the cells off the rim (the cap's inner cells are the squarest), all cells if too few.
  std::vector<int> candidates;
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      if (i > 0 && i < nu - 1 && j > 0 && j < nv - 1) candidates.push_back(i + nu * j);
    }
  }
  if (static_cast<long long>(candidates.size()) < splits) {
    candidates.resize(static_cast<size_t>(cap_quads));
    for (int c = 0; c < cap_quads; ++c) candidates[static_cast<size_t>(c)] = c;
  }
  std::vector<char> split(static_cast<size_t>(cap_quads), 0);
  const auto count = static_cast<long long>(candidates.size());
  for (long long s = 0; s < splits; ++s) split[static_cast<size_t>(candidates[static_cast<size_t>((2 * s + 1) * count / (2 * splits))])] = 1;

  // The side's quads split along their shorter diagonal; the cap's along the diagonal whose worse
  // triangle is the better one (near the grid's corners the rim can squeeze a cell either way).
  TriMesh mesh;
  const TriMesh side_triangles = triangulate_quads(quads);
  const Eigen::Index side_faces = side_triangles.F.rows();
  mesh.V.resize(V.rows() + splits, 3);
  mesh.V.topRows(V.rows()) = V;
  mesh.F.resize(params.target_triangles - params.target_triangles % 2, 3);
  mesh.F.topRows(side_faces) = side_triangles.F;
  Eigen::Index face = side_faces, centre = V.rows();
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const std::array<int, 4> quad{g(i, j), g(i, j + 1), g(i + 1, j + 1), g(i + 1, j)};
      if (split[static_cast<size_t>(i + nu * j)] != 0) {
        mesh.V.row(centre) = into_cut(0.25 * (at(quad[0]) + at(quad[1]) + at(quad[2]) + at(quad[3]))).transpose();
        for (int k = 0; k < 4; ++k) mesh.F.row(face++) << quad[static_cast<size_t>(k)], quad[static_cast<size_t>((k + 1) % 4)], static_cast<int>(centre);
        ++centre;
        continue;
      }
      const auto q = [&](int a, int b, int c) { return triangle_quality(at(quad[a]), at(quad[b]), at(quad[c])); };
      if (std::min(q(0, 1, 2), q(0, 2, 3)) >= std::min(q(0, 1, 3), q(1, 2, 3))) {
        mesh.F.row(face++) << quad[0], quad[1], quad[2];
        mesh.F.row(face++) << quad[0], quad[2], quad[3];
      } else {
        mesh.F.row(face++) << quad[0], quad[1], quad[3];
        mesh.F.row(face++) << quad[1], quad[2], quad[3];
      }
    }
  }
  if (face != mesh.F.rows() || centre != mesh.V.rows()) throw EngineError("Bezier last: the triangle count does not add up");
  return mesh;
}

}  // namespace lastcut
