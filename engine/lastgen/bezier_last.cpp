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
#include "engine/lastgen/top_cap.hpp"
#include "engine/subdiv/sample_surface.hpp"

namespace lastcut {
namespace {

constexpr int kTypicalControlQuads = 1500;  // n grows once the control mesh has this many quads
constexpr int kCellSearch = 3;              // box sides tried around the proportional ones
// The share of the count held back from the side's box for the flat cap, which takes whatever the side
// leaves (top_cap.hpp). The cap's own cells of the box bring most of what it needs; this share brings
// its triangles to about the side's size (the cut is 4.0 % of the EU 42 last's area; at 5000 triangles
// the cap's mean triangle is 13.6 mm^2 against the side's 15.7, at 12000 5.3 against 6.6).
constexpr double kCapShare = 0.01;

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
  const LastSideMesh side = last_side_mesh(shape, params, cells_for_count(high - low, n, static_cast<int>((1.0 - kCapShare) * params.target_triangles)));
  const QuadMesh quads = subdivide_bezier(side.control, n, SampleSpread::EvenAtExtraordinary).quads;

  // Output vertex v < #control V is the limit point of control vertex v (all of them are used).
  const std::vector<int> loop = boundary_loop(quads, side.cap_corners[0]);
  const int nu = n * side.cap_cells_u, nv = n * side.cap_cells_v;
  const auto loop_size = static_cast<size_t>(2 * (nu + nv));
  if (loop.size() != loop_size || loop[static_cast<size_t>(nu)] != side.cap_corners[1] ||
      loop[static_cast<size_t>(nu + nv)] != side.cap_corners[2] || loop[static_cast<size_t>(2 * nu + nv)] != side.cap_corners[3]) {
    throw EngineError("Bezier last: the rim does not match the cap's cells");
  }

  // The flat cap gets every triangle the side leaves (top_cap.hpp).
  const TriMesh side_triangles = triangulate_quads(quads);
  TopCapInput cap_input;
  cap_input.V = &quads.V;
  cap_input.loop = loop;
  cap_input.nu = nu, cap_input.nv = nv;
  cap_input.cut_point_mm = side.cut_point_mm;
  cap_input.cut_normal = side.cut_normal;
  cap_input.triangles = static_cast<int>(params.target_triangles - params.target_triangles % 2 - side_triangles.F.rows());
  const TopCap cap = top_cap(cap_input);
  TriMesh mesh;
  mesh.V.resize(quads.V.rows() + cap.V.rows(), 3);
  mesh.V << quads.V, cap.V;
  mesh.F.resize(side_triangles.F.rows() + cap.F.rows(), 3);
  mesh.F << side_triangles.F, cap.F;
  return mesh;
}

}  // namespace lastcut
