#include "engine/subdiv/sample_surface.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

// The parameters of step s (0..n) along edge k of a face, running from corner k to corner k + 1.
Eigen::Vector2d edge_parameter(int k, int s, int n) {
  const double t = static_cast<double>(s) / n, back = static_cast<double>(n - s) / n;
  switch (k) {
    case 0: return {t, 0.0};
    case 1: return {1.0, t};
    case 2: return {back, 1.0};
    default: return {0.0, back};
  }
}

// Directions (in (u, v)) of the next and the previous edge leaving corner k of a face.
constexpr double kNextDirection[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
constexpr double kPrevDirection[4][2] = {{0, 1}, {-1, 0}, {0, -1}, {1, 0}};
constexpr double kCornerUv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

// Warp strength along one edge leaving a corner: the first segment of n is about |S'(0)| / n long,
// the mean chord / n; a = chord / |S'(0)| - 1 makes them match (w'(0) = 1 + a).
double edge_warp(const BezierPatch& patch, int k, const double (&direction)[2], const Eigen::Vector3d& far_corner) {
  const PatchPoint corner = evaluate_patch(patch, kCornerUv[k][0], kCornerUv[k][1]);
  const double speed = (direction[0] * corner.du + direction[1] * corner.dv).norm();
  const double chord = (far_corner - corner.position).norm();
  if (speed <= 0.0) return 0.0;
  return std::clamp(chord / speed - 1.0, -0.3, 0.5);
}

// Per face corner: warp strengths along its next and previous edge (0 at regular and boundary vertices).
std::vector<std::array<double, 8>> corner_warps(const QuadMesh& control, const QuadTopology& topology,
                                                const std::vector<BezierPatch>& patches) {
  std::vector<std::array<double, 8>> warps(static_cast<size_t>(control.quad_count()), std::array<double, 8>{});
  for (int q = 0; q < control.quad_count(); ++q) {
    const BezierPatch& patch = patches[static_cast<size_t>(q)];
    for (int k = 0; k < 4; ++k) {
      const int v = control.Q(q, k);
      if (topology.valence(v) == 4 || topology.on_boundary[static_cast<size_t>(v)]) continue;
      const int next = (k + 1) % 4, prev = (k + 3) % 4;
      warps[static_cast<size_t>(q)][static_cast<size_t>(2 * k)] =
          edge_warp(patch, k, kNextDirection[k], patch_position(patch, kCornerUv[next][0], kCornerUv[next][1]));
      warps[static_cast<size_t>(q)][static_cast<size_t>(2 * k + 1)] =
          edge_warp(patch, k, kPrevDirection[k], patch_position(patch, kCornerUv[prev][0], kCornerUv[prev][1]));
    }
  }
  return warps;
}

// (u, v) moved by the warps of the face's extraordinary corners (see SampleSpread).
Eigen::Vector2d warped(const std::array<double, 8>& warp, const Eigen::Vector2d& uv) {
  Eigen::Vector2d result = uv;
  for (int k = 0; k < 4; ++k) {
    const double a_next = warp[static_cast<size_t>(2 * k)], a_prev = warp[static_cast<size_t>(2 * k + 1)];
    if (a_next == 0.0 && a_prev == 0.0) continue;
    // Corner-local coordinates: s along the next edge, r along the previous edge.
    const Eigen::Vector2d offset = uv - Eigen::Vector2d(kCornerUv[k][0], kCornerUv[k][1]);
    const double s = offset.x() * kNextDirection[k][0] + offset.y() * kNextDirection[k][1];
    const double r = offset.x() * kPrevDirection[k][0] + offset.y() * kPrevDirection[k][1];
    const double ds = a_next * s * (1 - s) * (1 - s) * (1 - r) * (1 - r);
    const double dr = a_prev * r * (1 - r) * (1 - r) * (1 - s) * (1 - s);
    result += ds * Eigen::Vector2d(kNextDirection[k][0], kNextDirection[k][1]) + dr * Eigen::Vector2d(kPrevDirection[k][0], kPrevDirection[k][1]);
  }
  return result;
}

}  // namespace

SubdividedSurface subdivide_bezier(const QuadMesh& control, int n, SampleSpread spread) {
  if (n < 1 || n > kMaxSubdivisionDetail) {
    throw EngineError("detail n = " + std::to_string(n) + " is out of range 1.." + std::to_string(kMaxSubdivisionDetail));
  }
  if (control.quad_count() == 0) throw EngineError("the control mesh has no quads");
  const long long quad_total = static_cast<long long>(control.quad_count()) * n * n;
  if (quad_total > kMaxSubdividedQuads) {
    throw EngineError("detail n = " + std::to_string(n) + " would make " + std::to_string(quad_total) + " quads from " +
                      std::to_string(control.quad_count()) + " (at most " + std::to_string(kMaxSubdividedQuads) + ")");
  }
  const QuadTopology topology = build_quad_topology(control);
  const std::vector<BezierPatch> patches = build_bezier_patches(control, topology);
  const std::vector<std::array<double, 8>> warps = spread == SampleSpread::EvenAtExtraordinary
                                                       ? corner_warps(control, topology, patches)
                                                       : std::vector<std::array<double, 8>>(static_cast<size_t>(control.quad_count()), std::array<double, 8>{});

  // Output vertex ids: used control vertices first, then edges, then face interiors.
  std::vector<int> corner_id(static_cast<size_t>(control.vertex_count()), -1);
  int used = 0;
  for (int v = 0; v < control.vertex_count(); ++v) {
    if (topology.faces_at(v) > 0) corner_id[static_cast<size_t>(v)] = used++;
  }
  const int inner = n - 1;
  const long long edge_base = used;
  const long long face_base = edge_base + static_cast<long long>(topology.edge_count()) * inner;
  const long long vertex_total = face_base + static_cast<long long>(control.quad_count()) * inner * inner;

  SubdividedSurface surface;
  surface.quads.V.resize(vertex_total, 3);
  surface.quads.Q.resize(quad_total, 4);
  surface.source_face.assign(static_cast<size_t>(vertex_total), -1);
  surface.source_uv.resize(vertex_total, 2);
  const auto place = [&surface, &patches, &warps](long long id, int q, const Eigen::Vector2d& grid_uv) {
    const Eigen::Vector2d uv = warped(warps[static_cast<size_t>(q)], grid_uv);
    surface.quads.V.row(id) = patch_position(patches[static_cast<size_t>(q)], uv.x(), uv.y()).transpose();
    surface.source_face[static_cast<size_t>(id)] = q;
    surface.source_uv.row(id) = uv.transpose();
  };
  for (int v = 0; v < control.vertex_count(); ++v) {
    if (corner_id[static_cast<size_t>(v)] < 0) continue;
    const int h = topology.half_edge_at(v, 0);
    place(corner_id[static_cast<size_t>(v)], h / 4, edge_parameter(h % 4, 0, n));
  }
  for (int e = 0; e < topology.edge_count(); ++e) {
    const int h = topology.edge_half_edge[static_cast<size_t>(e)];
    for (int s = 1; s < n; ++s) place(edge_base + static_cast<long long>(e) * inner + s - 1, h / 4, edge_parameter(h % 4, s, n));
  }

  // The output vertex at grid point (i, j) of face q.
  const auto grid_vertex = [&](int q, int i, int j) -> long long {
    int k = -1, s = 0;
    if (j == 0) {
      k = 0, s = i;
    } else if (i == n) {
      k = 1, s = j;
    } else if (j == n) {
      k = 2, s = n - i;
    } else if (i == 0) {
      k = 3, s = n - j;
    }
    if (k < 0) return face_base + static_cast<long long>(q) * inner * inner + (j - 1) * inner + (i - 1);
    if (s == 0) return corner_id[static_cast<size_t>(control.Q(q, k))];
    if (s == n) return corner_id[static_cast<size_t>(control.Q(q, (k + 1) % 4))];
    const int h = 4 * q + k;
    const int e = topology.edge_of[static_cast<size_t>(h)];
    const int step = topology.edge_half_edge[static_cast<size_t>(e)] == h ? s : n - s;
    return edge_base + static_cast<long long>(e) * inner + step - 1;
  };
  long long quad = 0;
  for (int q = 0; q < control.quad_count(); ++q) {
    for (int j = 1; j < n; ++j) {
      for (int i = 1; i < n; ++i) place(grid_vertex(q, i, j), q, {static_cast<double>(i) / n, static_cast<double>(j) / n});
    }
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i, ++quad) {
        surface.quads.Q.row(quad) << static_cast<int>(grid_vertex(q, i, j)), static_cast<int>(grid_vertex(q, i + 1, j)),
            static_cast<int>(grid_vertex(q, i + 1, j + 1)), static_cast<int>(grid_vertex(q, i, j + 1));
      }
    }
  }
  return surface;
}

std::vector<EdgeEndSpacing> edge_end_spacing(const QuadMesh& control, const SubdividedSurface& surface, int n) {
  const QuadTopology topology = build_quad_topology(control);
  // The output ids subdivide_bezier gives: used control vertices first, then n - 1 per edge.
  std::vector<int> corner_id(static_cast<size_t>(control.vertex_count()), -1);
  int used = 0;
  for (int v = 0; v < control.vertex_count(); ++v) {
    if (topology.faces_at(v) > 0) corner_id[static_cast<size_t>(v)] = used++;
  }
  const auto sample = [&surface](long long id) -> Eigen::Vector3d { return surface.quads.V.row(id).transpose(); };
  std::vector<EdgeEndSpacing> spacing(static_cast<size_t>(topology.edge_count()));
  for (int e = 0; e < topology.edge_count(); ++e) {
    const int h = topology.edge_half_edge[static_cast<size_t>(e)];
    EdgeEndSpacing& edge = spacing[static_cast<size_t>(e)];
    edge.from = control.Q(h / 4, h % 4), edge.to = control.Q(h / 4, (h + 1) % 4);
    std::vector<Eigen::Vector3d> points{sample(corner_id[static_cast<size_t>(edge.from)])};
    for (int s = 1; s < n; ++s) points.push_back(sample(used + static_cast<long long>(e) * (n - 1) + s - 1));
    points.push_back(sample(corner_id[static_cast<size_t>(edge.to)]));
    double mean = 0.0;
    for (int s = 0; s < n; ++s) mean += (points[static_cast<size_t>(s) + 1] - points[static_cast<size_t>(s)]).norm() / n;
    edge.first_ratio = (points[1] - points[0]).norm() / mean;
    edge.last_ratio = (points[static_cast<size_t>(n)] - points[static_cast<size_t>(n) - 1]).norm() / mean;
  }
  return spacing;
}

TriMesh triangulate_quads(const QuadMesh& quads) {
  TriMesh mesh;
  mesh.V = quads.V;
  mesh.F.resize(2 * quads.Q.rows(), 3);
  for (Eigen::Index q = 0; q < quads.Q.rows(); ++q) {
    const Eigen::Vector4i c = quads.Q.row(q).transpose();
    const double diagonal02 = (quads.V.row(c(0)) - quads.V.row(c(2))).squaredNorm();
    const double diagonal13 = (quads.V.row(c(1)) - quads.V.row(c(3))).squaredNorm();
    if (diagonal02 <= diagonal13) {
      mesh.F.row(2 * q) << c(0), c(1), c(2);
      mesh.F.row(2 * q + 1) << c(0), c(2), c(3);
    } else {
      mesh.F.row(2 * q) << c(0), c(1), c(3);
      mesh.F.row(2 * q + 1) << c(1), c(2), c(3);
    }
  }
  return mesh;
}

}  // namespace lastcut
