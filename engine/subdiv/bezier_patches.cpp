#include "engine/subdiv/bezier_patches.hpp"

#include <cmath>
#include <numbers>

namespace lastcut {
namespace {

// The Bezier points one control vertex contributes to the patches of its faces.
struct VertexPoints {
  Eigen::Vector3d corner;
  std::vector<Eigen::Vector3d> edge;      // per edge neighbour e_j (valence)
  std::vector<Eigen::Vector3d> interior;  // per face of the fan
};

struct Ring {
  Eigen::Vector3d v;
  std::vector<Eigen::Vector3d> e;  // valence
  std::vector<Eigen::Vector3d> f;  // faces of the fan
};

Ring ring_of(const QuadMesh& mesh, const QuadTopology& topology, int vertex) {
  Ring ring;
  ring.v = mesh.V.row(vertex).transpose();
  const int faces = topology.faces_at(vertex);
  for (int j = 0; j < faces; ++j) {
    const int h = topology.half_edge_at(vertex, j);
    const int q = h / 4, k = h % 4;
    ring.e.push_back(mesh.V.row(mesh.Q(q, (k + 1) % 4)).transpose());
    ring.f.push_back(mesh.V.row(mesh.Q(q, (k + 2) % 4)).transpose());
  }
  if (topology.on_boundary[static_cast<size_t>(vertex)]) {
    const int h = topology.half_edge_at(vertex, faces - 1);
    ring.e.push_back(mesh.V.row(mesh.Q(h / 4, (h + 3) % 4)).transpose());
  }
  return ring;
}

Eigen::Vector3d interior_point(const Ring& ring, int j, double n) {
  const size_t next = (static_cast<size_t>(j) + 1) % ring.e.size();
  return (n * ring.v + 2.0 * (ring.e[static_cast<size_t>(j)] + ring.e[next]) + ring.f[static_cast<size_t>(j)]) / (n + 5.0);
}

VertexPoints interior_vertex(const Ring& ring) {
  const int n = static_cast<int>(ring.e.size());
  const double nd = n;
  VertexPoints points;
  Eigen::Vector3d sum_e = Eigen::Vector3d::Zero(), sum_f = Eigen::Vector3d::Zero();
  for (int j = 0; j < n; ++j) {
    sum_e += ring.e[static_cast<size_t>(j)];
    sum_f += ring.f[static_cast<size_t>(j)];
  }
  points.corner = (nd * nd * ring.v + 4.0 * sum_e + sum_f) / (nd * (nd + 5.0));
  for (int j = 0; j < n; ++j) points.interior.push_back(interior_point(ring, j, nd));
  if (n == 4) {
    // The tangent rule equals this average for valence 4; the average keeps regular patches exact.
    for (int i = 0; i < n; ++i) {
      points.edge.push_back(0.5 * (points.interior[static_cast<size_t>((i + n - 1) % n)] + points.interior[static_cast<size_t>(i)]));
    }
    return points;
  }
  const double angle = 2.0 * std::numbers::pi / nd;
  const double a_n = 1.0 + std::cos(angle) + std::cos(angle / 2.0) * std::sqrt(2.0 * (9.0 + std::cos(angle)));
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d tangent = Eigen::Vector3d::Zero();
    for (int j = 0; j < n; ++j) {
      const double c0 = std::cos(angle * (j - i)), c1 = std::cos(angle * (j - i + 1));
      tangent += a_n * c0 * ring.e[static_cast<size_t>(j)] + (c0 + c1) * ring.f[static_cast<size_t>(j)];
    }
    const Eigen::Vector3d direction = tangent.normalized();
    const Eigen::Vector3d average =
        0.5 * (points.interior[static_cast<size_t>((i + n - 1) % n)] + points.interior[static_cast<size_t>(i)]);
    points.edge.push_back(points.corner + direction.dot(average - points.corner) * direction);
  }
  return points;
}

VertexPoints boundary_vertex(const Ring& ring) {
  const int valence = static_cast<int>(ring.e.size());
  const int faces = valence - 1;
  const Eigen::Vector3d& first = ring.e.front();
  const Eigen::Vector3d& last = ring.e.back();
  VertexPoints points;
  if (valence == 2) {
    points.corner = ring.v;
    points.edge = {ring.v + (first - ring.v) / 3.0, ring.v + (last - ring.v) / 3.0};
    points.interior = {(4.0 * ring.v + 2.0 * (first + last) + ring.f[0]) / 9.0};
    return points;
  }
  points.corner = (4.0 * ring.v + first + last) / 6.0;
  const double mirrored_valence = 2.0 * faces;
  for (int j = 0; j < faces; ++j) points.interior.push_back(interior_point(ring, j, mirrored_valence));
  points.edge.push_back(points.corner + (first - last) / 6.0);
  for (int i = 1; i < faces; ++i) {
    points.edge.push_back(0.5 * (points.interior[static_cast<size_t>(i - 1)] + points.interior[static_cast<size_t>(i)]));
  }
  points.edge.push_back(points.corner + (last - first) / 6.0);
  return points;
}

// Cubic Bernstein polynomials and their first and second derivatives at t.
struct Bernstein {
  std::array<double, 4> value, d1, d2;
  explicit Bernstein(double t) {
    const double s = 1.0 - t;
    value = {s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t};
    d1 = {-3.0 * s * s, 3.0 * s * (s - 2.0 * t), 3.0 * t * (2.0 * s - t), 3.0 * t * t};
    d2 = {6.0 * s, 6.0 * (3.0 * t - 2.0), 6.0 * (1.0 - 3.0 * t), 6.0 * t};
  }
};

}  // namespace

std::vector<BezierPatch> build_bezier_patches(const QuadMesh& mesh, const QuadTopology& topology) {
  std::vector<VertexPoints> vertex_points(static_cast<size_t>(mesh.vertex_count()));
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    if (topology.faces_at(v) == 0) continue;
    const Ring ring = ring_of(mesh, topology, v);
    vertex_points[static_cast<size_t>(v)] =
        topology.on_boundary[static_cast<size_t>(v)] ? boundary_vertex(ring) : interior_vertex(ring);
  }
  // Where corner k's points go in the 4 x 4 net: corner, along the next edge, along the previous
  // edge, interior (as (i, j) pairs).
  static constexpr int kSlots[4][4][2] = {{{0, 0}, {1, 0}, {0, 1}, {1, 1}},
                                          {{3, 0}, {3, 1}, {2, 0}, {2, 1}},
                                          {{3, 3}, {2, 3}, {3, 2}, {2, 2}},
                                          {{0, 3}, {0, 2}, {1, 3}, {1, 2}}};
  std::vector<BezierPatch> patches(static_cast<size_t>(mesh.quad_count()));
  for (int q = 0; q < mesh.quad_count(); ++q) {
    BezierPatch& patch = patches[static_cast<size_t>(q)];
    for (int k = 0; k < 4; ++k) {
      const int h = 4 * q + k;
      const VertexPoints& points = vertex_points[static_cast<size_t>(mesh.Q(q, k))];
      const auto j = static_cast<size_t>(topology.ring_position[static_cast<size_t>(h)]);
      const auto slot = [&patch, k](int which) -> Eigen::Vector3d& {
        return patch.b[static_cast<size_t>(kSlots[k][which][0] + 4 * kSlots[k][which][1])];
      };
      slot(0) = points.corner;
      slot(1) = points.edge[j];
      slot(2) = points.edge[(j + 1) % points.edge.size()];
      slot(3) = points.interior[j];
    }
  }
  return patches;
}

PatchPoint evaluate_patch(const BezierPatch& patch, double u, double v) {
  const Bernstein bu(u), bv(v);
  PatchPoint point;
  point.position = point.du = point.dv = point.duu = point.duv = point.dvv = Eigen::Vector3d::Zero();
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector3d& b = patch.at(i, j);
      const auto ii = static_cast<size_t>(i), jj = static_cast<size_t>(j);
      point.position += bu.value[ii] * bv.value[jj] * b;
      point.du += bu.d1[ii] * bv.value[jj] * b;
      point.dv += bu.value[ii] * bv.d1[jj] * b;
      point.duu += bu.d2[ii] * bv.value[jj] * b;
      point.duv += bu.d1[ii] * bv.d1[jj] * b;
      point.dvv += bu.value[ii] * bv.d2[jj] * b;
    }
  }
  return point;
}

Eigen::Vector3d patch_position(const BezierPatch& patch, double u, double v) {
  const double su = 1.0 - u, sv = 1.0 - v;
  const double bu[4] = {su * su * su, 3.0 * u * su * su, 3.0 * u * u * su, u * u * u};
  const double bv[4] = {sv * sv * sv, 3.0 * v * sv * sv, 3.0 * v * v * sv, v * v * v};
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  for (int j = 0; j < 4; ++j) {
    Eigen::Vector3d row = Eigen::Vector3d::Zero();
    for (int i = 0; i < 4; ++i) row += bu[i] * patch.at(i, j);
    position += bv[j] * row;
  }
  return position;
}

}  // namespace lastcut
