#include "engine/subdiv/bezier_patches.hpp"

#include <cmath>
#include <functional>
#include <numbers>
#include <type_traits>

namespace lastcut {
namespace {

// The Bezier points one control vertex contributes to the patches of its faces. Point is a position
// (Eigen::Vector3d, mm) or the weights of the ring's points (Eigen::VectorXd, one entry per ring point).
template <class Point>
struct VertexPointsOf {
  Point corner;
  std::vector<Point> edge;      // per edge neighbour e_j (valence)
  std::vector<Point> interior;  // per face of the fan
};

template <class Point>
struct RingOf {
  Point v;
  std::vector<Point> e;  // valence
  std::vector<Point> f;  // faces of the fan
};

using VertexPoints = VertexPointsOf<Eigen::Vector3d>;
using Ring = RingOf<Eigen::Vector3d>;

// The ring's control vertices: v, then e_0 .. e_valence-1, then f_0 .. f_faces-1.
std::vector<int> ring_ids(const QuadMesh& mesh, const QuadTopology& topology, int vertex) {
  std::vector<int> e, f;
  const int faces = topology.faces_at(vertex);
  for (int j = 0; j < faces; ++j) {
    const int h = topology.half_edge_at(vertex, j);
    const int q = h / 4, k = h % 4;
    e.push_back(mesh.Q(q, (k + 1) % 4));
    f.push_back(mesh.Q(q, (k + 2) % 4));
  }
  if (topology.on_boundary[static_cast<size_t>(vertex)]) {
    const int h = topology.half_edge_at(vertex, faces - 1);
    e.push_back(mesh.Q(h / 4, (h + 3) % 4));
  }
  std::vector<int> ids{vertex};
  ids.insert(ids.end(), e.begin(), e.end());
  ids.insert(ids.end(), f.begin(), f.end());
  return ids;
}

Ring ring_of(const QuadMesh& mesh, const QuadTopology& topology, int vertex) {
  const std::vector<int> ids = ring_ids(mesh, topology, vertex);
  const auto valence = static_cast<size_t>(topology.valence(vertex));
  Ring ring;
  ring.v = mesh.V.row(vertex).transpose();
  for (size_t i = 1; i < ids.size(); ++i) (i <= valence ? ring.e : ring.f).push_back(mesh.V.row(ids[i]).transpose());
  return ring;
}

// The ring with unit weights in place of positions: the formulas below then give each Bezier point's
// weights of the ring's control vertices (they are linear in the ring, but for the tangent rule).
RingOf<Eigen::VectorXd> unit_ring(int valence, int faces) {
  const int size = 1 + valence + faces;
  RingOf<Eigen::VectorXd> ring;
  ring.v = Eigen::VectorXd::Unit(size, 0);
  for (int j = 0; j < valence; ++j) ring.e.push_back(Eigen::VectorXd::Unit(size, 1 + j));
  for (int j = 0; j < faces; ++j) ring.f.push_back(Eigen::VectorXd::Unit(size, 1 + valence + j));
  return ring;
}

template <class Point>
Point interior_point(const RingOf<Point>& ring, int j, double n) {
  const size_t next = (static_cast<size_t>(j) + 1) % ring.e.size();
  return (n * ring.v + 2.0 * (ring.e[static_cast<size_t>(j)] + ring.e[next]) + ring.f[static_cast<size_t>(j)]) / (n + 5.0);
}

// With Point = VectorXd (weights) the edge points at an extraordinary vertex take the regular rule's
// average M_i: the tangent projection is not linear in the ring.
template <class Point>
VertexPointsOf<Point> interior_vertex(const RingOf<Point>& ring) {
  const int n = static_cast<int>(ring.e.size());
  const double nd = n;
  VertexPointsOf<Point> points;
  Point sum_e = 0.0 * ring.v, sum_f = 0.0 * ring.v;
  for (int j = 0; j < n; ++j) {
    sum_e += ring.e[static_cast<size_t>(j)];
    sum_f += ring.f[static_cast<size_t>(j)];
  }
  points.corner = (nd * nd * ring.v + 4.0 * sum_e + sum_f) / (nd * (nd + 5.0));
  for (int j = 0; j < n; ++j) points.interior.push_back(interior_point(ring, j, nd));
  for (int i = 0; i < n; ++i) {
    // The tangent rule equals this average for valence 4; the average keeps regular patches exact.
    points.edge.push_back(0.5 * (points.interior[static_cast<size_t>((i + n - 1) % n)] + points.interior[static_cast<size_t>(i)]));
  }
  if constexpr (std::is_same_v<Point, Eigen::Vector3d>) {
    if (n == 4) return points;
    const double angle = 2.0 * std::numbers::pi / nd;
    const double a_n = 1.0 + std::cos(angle) + std::cos(angle / 2.0) * std::sqrt(2.0 * (9.0 + std::cos(angle)));
    for (int i = 0; i < n; ++i) {
      Eigen::Vector3d tangent = Eigen::Vector3d::Zero();
      for (int j = 0; j < n; ++j) {
        const double c0 = std::cos(angle * (j - i)), c1 = std::cos(angle * (j - i + 1));
        tangent += a_n * c0 * ring.e[static_cast<size_t>(j)] + (c0 + c1) * ring.f[static_cast<size_t>(j)];
      }
      const Eigen::Vector3d direction = tangent.normalized();
      const Eigen::Vector3d average = points.edge[static_cast<size_t>(i)];
      points.edge[static_cast<size_t>(i)] = points.corner + direction.dot(average - points.corner) * direction;
    }
  }
  return points;
}

template <class Point>
VertexPointsOf<Point> boundary_vertex(const RingOf<Point>& ring) {
  const int valence = static_cast<int>(ring.e.size());
  const int faces = valence - 1;
  const Point& first = ring.e.front();
  const Point& last = ring.e.back();
  VertexPointsOf<Point> points;
  if (valence == 2) {
    points.corner = ring.v;
    points.edge = {Point(ring.v + (first - ring.v) / 3.0), Point(ring.v + (last - ring.v) / 3.0)};
    points.interior = {Point((4.0 * ring.v + 2.0 * (first + last) + ring.f[0]) / 9.0)};
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

// Where corner k's points go in the 4 x 4 net: corner, along the next edge, along the previous
// edge, interior (as (i, j) pairs).
constexpr int kSlots[4][4][2] = {{{0, 0}, {1, 0}, {0, 1}, {1, 1}},
                                 {{3, 0}, {3, 1}, {2, 0}, {2, 1}},
                                 {{3, 3}, {2, 3}, {3, 2}, {2, 2}},
                                 {{0, 3}, {0, 2}, {1, 3}, {1, 2}}};

// Per quad, the 16 entries b[i + 4 j] from the points of its four corner vertices.
template <class Point, class Net>
void assemble_nets(const QuadMesh& mesh, const QuadTopology& topology, const std::vector<VertexPointsOf<Point>>& vertex_points,
                   std::vector<Net>& nets, const std::function<void(Net&, size_t, int, const Point&)>& put) {
  nets.resize(static_cast<size_t>(mesh.quad_count()));
  for (int q = 0; q < mesh.quad_count(); ++q) {
    for (int k = 0; k < 4; ++k) {
      const int h = 4 * q + k;
      const int vertex = mesh.Q(q, k);
      const VertexPointsOf<Point>& points = vertex_points[static_cast<size_t>(vertex)];
      const auto j = static_cast<size_t>(topology.ring_position[static_cast<size_t>(h)]);
      const auto slot = [k](int which) { return static_cast<size_t>(kSlots[k][which][0] + 4 * kSlots[k][which][1]); };
      Net& net = nets[static_cast<size_t>(q)];
      put(net, slot(0), vertex, points.corner);
      put(net, slot(1), vertex, points.edge[j]);
      put(net, slot(2), vertex, points.edge[(j + 1) % points.edge.size()]);
      put(net, slot(3), vertex, points.interior[j]);
    }
  }
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
  std::vector<BezierPatch> patches;
  assemble_nets<Eigen::Vector3d, BezierPatch>(mesh, topology, vertex_points, patches,
      [](BezierPatch& patch, size_t slot, int, const Eigen::Vector3d& point) { patch.b[slot] = point; });
  return patches;
}

std::vector<PatchWeights> bezier_patch_weights(const QuadMesh& mesh, const QuadTopology& topology) {
  std::vector<VertexPointsOf<Eigen::VectorXd>> vertex_points(static_cast<size_t>(mesh.vertex_count()));
  std::vector<std::vector<int>> ids(static_cast<size_t>(mesh.vertex_count()));
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    if (topology.faces_at(v) == 0) continue;
    ids[static_cast<size_t>(v)] = ring_ids(mesh, topology, v);
    const RingOf<Eigen::VectorXd> ring = unit_ring(topology.valence(v), topology.faces_at(v));
    vertex_points[static_cast<size_t>(v)] =
        topology.on_boundary[static_cast<size_t>(v)] ? boundary_vertex(ring) : interior_vertex(ring);
  }
  std::vector<PatchWeights> weights;
  assemble_nets<Eigen::VectorXd, PatchWeights>(mesh, topology, vertex_points, weights,
      [&ids](PatchWeights& net, size_t slot, int vertex, const Eigen::VectorXd& point) {
        const std::vector<int>& ring = ids[static_cast<size_t>(vertex)];
        for (Eigen::Index i = 0; i < point.size(); ++i) {
          if (point(i) != 0.0) net.b[slot].emplace_back(ring[static_cast<size_t>(i)], point(i));
        }
      });
  return weights;
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
