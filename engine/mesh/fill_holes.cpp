// Ring-and-zipper hole patches, faired by the bi-Laplacian; see fill_holes.hpp.
#include "engine/mesh/fill_holes.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <numbers>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/core/mesh_topology.hpp"
#include "engine/mesh/bilaplacian_fairing.hpp"

namespace lastcut {
namespace {

// A ring of patch vertices: indices into the growing vertex list, their positions in the loop's
// plane (mm, relative to the centroid) and their fractions of the turn around the centroid in [0, 1),
// increasing, measured from the loop's first vertex in the loop's direction.
struct Ring {
  std::vector<int> vertex;
  std::vector<Eigen::Vector2d> point;
  std::vector<double> fraction;
};

// Triangles between an outer and an inner ring running the same way: each step takes the ring whose
// next vertex comes first by fraction. Outer edges are used reversed (the outer ring's faces lie
// on its other side), inner edges forward (the next band uses them reversed). Returns false, adding
// nothing, when a triangle would be folded or degenerate in the plane (turn_sign: +1 when the rings
// run counter-clockwise in the plane's (u, v) coordinates).
bool zip_rings(const Ring& outer, const Ring& inner, double turn_sign, double smallest_area_mm2,
               std::vector<Eigen::RowVector3i>& faces) {
  const size_t n_outer = outer.vertex.size(), n_inner = inner.vertex.size();
  const auto outer_at = [&](size_t a) { return a < n_outer ? outer.fraction[a] - outer.fraction[0] : 1.0; };
  const auto inner_at = [&](size_t b) { return b < n_inner ? inner.fraction[b] - inner.fraction[0] : 1.0; };
  const auto unfolded = [&](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    const Eigen::Vector2d e = q - p, f = r - p;
    return -turn_sign * 0.5 * (e.x() * f.y() - e.y() * f.x()) > smallest_area_mm2;  // faces run against the rings
  };
  std::vector<Eigen::RowVector3i> band;
  size_t a = 0, b = 0;
  while (a < n_outer || b < n_inner) {
    if (b == n_inner || (a < n_outer && outer_at(a + 1) <= inner_at(b + 1))) {
      if (!unfolded(outer.point[(a + 1) % n_outer], outer.point[a % n_outer], inner.point[b % n_inner])) return false;
      band.emplace_back(outer.vertex[(a + 1) % n_outer], outer.vertex[a % n_outer], inner.vertex[b % n_inner]);
      ++a;
    } else {
      if (!unfolded(inner.point[b % n_inner], inner.point[(b + 1) % n_inner], outer.point[a % n_outer])) return false;
      band.emplace_back(inner.vertex[b % n_inner], inner.vertex[(b + 1) % n_inner], outer.vertex[a % n_outer]);
      ++b;
    }
  }
  faces.insert(faces.end(), band.begin(), band.end());
  return true;
}

// The loop's plane: centroid and outward unit normal (Newell's normal of the loop, reversed: the loop
// runs clockwise around the hole seen from outside), with u x v = normal.
struct LoopPlane {
  Eigen::Vector3d centroid, normal, u, v;
};

LoopPlane loop_plane(const Eigen::MatrixXd& V, const std::vector<int>& loop) {
  LoopPlane plane;
  plane.centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d newell = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector3d a = V.row(loop[i]), b = V.row(loop[(i + 1) % loop.size()]);
    plane.centroid += a / static_cast<double>(loop.size());
    newell += a.cross(b);
  }
  plane.normal = newell.norm() > 0.0 ? Eigen::Vector3d(-newell.normalized()) : Eigen::Vector3d::UnitZ();
  plane.u = plane.normal.unitOrthogonal();
  plane.v = plane.normal.cross(plane.u);
  return plane;
}

// sin 15 degrees: the smallest angle between a hole's edge and the ray from its centre to it that the
// ring patch takes as it is (steeper tooth flanks are trimmed).
constexpr double kSmallestEdgeToRaySine = 0.26;

// How the loop turns around its centroid seen from its plane: the signed angle of each edge (loop[i]
// to loop[i+1]), and whether every edge faces the centroid, once round (star-shaped, with no edge
// steeper than kSmallestEdgeToRaySine to its ray).
struct LoopTurns {
  std::vector<double> step;
  std::vector<char> facing;  // per edge: turns the loop's way and is not a tooth's flank
  double sign = 1.0;         // the way round: +1 or -1
  bool star_shaped = false;  // once round, every edge facing
};

LoopTurns loop_turns(const Eigen::MatrixXd& V, const std::vector<int>& loop, const LoopPlane& plane) {
  LoopTurns turns;
  const auto flat = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d d = p - plane.centroid;
    return Eigen::Vector2d(d.dot(plane.u), d.dot(plane.v));
  };
  double total = 0.0;
  std::vector<double> sine;  // of the angle between each edge and the ray to its start, signed
  for (size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector2d p = flat(V.row(loop[i])), q = flat(V.row(loop[(i + 1) % loop.size()]));
    double step = std::atan2(q.y(), q.x()) - std::atan2(p.y(), p.x());
    if (step < -std::numbers::pi) step += 2.0 * std::numbers::pi;
    if (step > std::numbers::pi) step -= 2.0 * std::numbers::pi;
    turns.step.push_back(step);
    const Eigen::Vector2d e = q - p;
    sine.push_back((p.x() * e.y() - p.y() * e.x()) / std::max(p.norm() * e.norm(), 1e-12));
    total += step;
  }
  turns.sign = total > 0.0 ? 1.0 : -1.0;
  // An edge nearly along the ray from the centre (a tooth's flank) turns forward by a sliver only: the
  // ring patch's band there would be a sliver too. Such edges count as turning back.
  for (size_t i = 0; i < loop.size(); ++i)
    turns.facing.push_back(turns.sign * turns.step[i] > 0.0 && turns.sign * sine[i] >= kSmallestEdgeToRaySine);
  turns.star_shaped = std::abs(std::abs(total) - 2.0 * std::numbers::pi) < 1e-6 &&
                      std::all_of(turns.facing.begin(), turns.facing.end(), [](char f) { return f != 0; });
  return turns;
}

// The hole a boundary loop belongs to: the id carried by any of its vertices, or -1.
int hole_of_loop(const std::vector<int>& loop, const std::vector<int>& hole_of_vertex) {
  for (int v : loop)
    if (hole_of_vertex[static_cast<size_t>(v)] >= 0) return hole_of_vertex[static_cast<size_t>(v)];
  return -1;
}

// Drops the faces with remove[f] != 0 and the vertices no face uses any more; hole_of_vertex follows
// the renumbering.
void drop_faces(TriMesh& mesh, const std::vector<char>& remove, std::vector<int>& hole_of_vertex) {
  std::vector<int> new_index(static_cast<size_t>(mesh.V.rows()), -1);
  const auto kept_count = static_cast<Eigen::Index>(std::count(remove.begin(), remove.end(), 0));
  Eigen::MatrixXi kept(kept_count, 3);
  int next_face = 0, next_vertex = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    if (remove[static_cast<size_t>(f)]) continue;
    for (int k = 0; k < 3; ++k) {
      int& index = new_index[static_cast<size_t>(mesh.F(f, k))];
      if (index < 0) index = next_vertex++;
      kept(next_face, k) = index;
    }
    ++next_face;
  }
  Eigen::MatrixXd vertices(next_vertex, 3);
  std::vector<int> hole_of_kept(static_cast<size_t>(next_vertex), -1);
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
    const int index = new_index[static_cast<size_t>(v)];
    if (index < 0) continue;
    vertices.row(index) = mesh.V.row(v);
    hole_of_kept[static_cast<size_t>(index)] = hole_of_vertex[static_cast<size_t>(v)];
  }
  mesh.V = std::move(vertices);
  mesh.F = std::move(kept);
  hole_of_vertex = std::move(hole_of_kept);
}

// A scanner's ragged hole edge has teeth: edges that turn back around the hole's centre. Removing the
// face behind each such edge (a few rounds) widens the hole to a star-shaped one, which the ring patch
// covers without a fold; the patch then replaces those faces along the surface. Only loops of the
// holes to close are touched (hole_of_vertex >= 0 on them); the vertices of every removed face join
// that hole, so a widened hole is still known as the scan's hole it grew from. Returns the number of
// faces removed. topology: mesh's, rebuilt after each round that drops faces so that it stays so.
int trim_holes_to_star_shapes(TriMesh& mesh, MeshTopology& topology, std::vector<int>& hole_of_vertex) {
  constexpr int kRounds = 30;
  int removed_total = 0;
  for (int round = 0; round < kRounds; ++round) {
    std::vector<char> remove(static_cast<size_t>(mesh.F.rows()), 0);
    std::vector<int> hole_of_face(static_cast<size_t>(mesh.F.rows()), -1);
    int removed = 0;
    for (const std::vector<int>& loop : topology.boundary_loops) {
      const int hole = hole_of_loop(loop, hole_of_vertex);
      if (loop.size() < 4 || hole < 0) continue;
      const LoopTurns turns = loop_turns(mesh.V, loop, loop_plane(mesh.V, loop));
      if (turns.star_shaped || std::abs(std::abs(std::accumulate(turns.step.begin(), turns.step.end(), 0.0)) -
                                        2.0 * std::numbers::pi) > 1e-6)
        continue;  // already star-shaped, or not once round its centre (no trimming makes it so)
      for (size_t i = 0; i < loop.size(); ++i) {
        if (turns.facing[i]) continue;
        const int h = topology.find_half_edge(loop[i], loop[(i + 1) % loop.size()]);
        if (h >= 0 && !remove[static_cast<size_t>(h / 3)]) {
          remove[static_cast<size_t>(h / 3)] = 1, hole_of_face[static_cast<size_t>(h / 3)] = hole, ++removed;
        }
      }
    }
    // Removing single faces can pinch the edge (two loops through one vertex) or cut off an island:
    // the faces at a pinch go too, and only the largest piece of the surface stays.
    if (removed > 0 && topology.first_pinch_vertex < 0) {
      const MeshTopology trimmed = build_mesh_topology(mesh.F, mesh.V.rows(), remove);
      if (trimmed.first_pinch_vertex >= 0) {
        const int hole = hole_of_vertex[static_cast<size_t>(trimmed.first_pinch_vertex)];
        for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
          for (int k = 0; k < 3; ++k)
            if (mesh.F(f, k) == trimmed.first_pinch_vertex && !remove[static_cast<size_t>(f)])
              remove[static_cast<size_t>(f)] = 1, hole_of_face[static_cast<size_t>(f)] = hole, ++removed;
      }
      std::vector<char> kept_faces(remove.size());
      for (size_t f = 0; f < remove.size(); ++f) kept_faces[f] = !remove[f];
      int components = 0;
      const std::vector<int> component = face_components(trimmed, kept_faces, components);
      if (components > 1) {
        const std::vector<double> areas = component_areas(component, components, triangle_areas(mesh));
        const int largest = static_cast<int>(std::max_element(areas.begin(), areas.end()) - areas.begin());
        for (size_t f = 0; f < remove.size(); ++f)
          if (!remove[f] && component[f] != largest) remove[f] = 1, ++removed;
      }
    }
    if (removed == 0) break;
    removed_total += removed;
    for (size_t f = 0; f < remove.size(); ++f) {
      if (hole_of_face[f] < 0) continue;
      for (int k = 0; k < 3; ++k) {
        int& hole = hole_of_vertex[static_cast<size_t>(mesh.F(static_cast<Eigen::Index>(f), k))];
        if (hole < 0) hole = hole_of_face[f];
      }
    }
    drop_faces(mesh, remove, hole_of_vertex);
    // Dropping renumbers faces and vertices: the next round and the patches read the trimmed mesh.
    topology = build_mesh_topology(mesh.F, mesh.V.rows());
  }
  return removed_total;
}

// Closes one loop (mesh vertex indices in the faces' direction) with rings laid out flat in the loop's
// plane: copies of the loop (projected on the plane) shrunk towards its centroid by 1 - j/R, R about
// the loop's mean radius over its mean edge length. A ring keeps the directions (from the centroid) of
// every loop vertex, or of every second one of the ring outside it once its edges would be shorter
// than half the loop's. For a loop that is star-shaped around its centroid (a scan hole, however
// ragged its edge, once trimmed) a band between two shrunk copies with the same directions is a row
// of trapezoids and cannot fold; a band that halves the directions is checked triangle by triangle in
// the plane and, where one would fold, built without halving. Returns false, adding nothing, when the
// loop is not star-shaped. New vertices are appended to `vertices` (shared by all patches; vertices[i]
// will be mesh vertex first_new_index + i), triangles to `faces`, the plane's normal once per new
// vertex to `normals`.
bool ring_patch(const Eigen::MatrixXd& V, const std::vector<int>& loop, int first_new_index,
                std::vector<Eigen::RowVector3d>& vertices, std::vector<Eigen::RowVector3i>& faces,
                std::vector<Eigen::Vector3d>& normals) {
  const size_t count = loop.size();
  const LoopPlane plane = loop_plane(V, loop);
  const LoopTurns turns = loop_turns(V, loop, plane);
  if (!turns.star_shaped) return false;
  Ring outer;
  double turned = 0.0, mean_radius_mm = 0.0, perimeter_mm = 0.0;
  for (size_t i = 0; i < count; ++i) {
    const Eigen::Vector3d d = Eigen::Vector3d(V.row(loop[i])) - plane.centroid;
    outer.point.emplace_back(d.dot(plane.u), d.dot(plane.v));
    mean_radius_mm += outer.point.back().norm() / static_cast<double>(count);
    perimeter_mm += (V.row(loop[(i + 1) % count]) - V.row(loop[i])).norm();
    outer.vertex.push_back(loop[i]);
    outer.fraction.push_back(turned / (2.0 * std::numbers::pi));
    turned += turns.sign * turns.step[i];
  }
  const double edge_mm = perimeter_mm / static_cast<double>(count);
  const double smallest_area_mm2 = 1e-6 * edge_mm * edge_mm;
  const std::vector<Eigen::Vector2d> loop_points = outer.point;
  const std::vector<double> loop_fractions = outer.fraction;
  const size_t vertices_before = vertices.size(), faces_before = faces.size(), normals_before = normals.size();
  std::vector<size_t> directions(count);  // loop vertex of each vertex of the current ring
  for (size_t i = 0; i < count; ++i) directions[i] = i;
  const int rings = std::max(1, static_cast<int>(std::lround(mean_radius_mm / edge_mm)));
  for (int j = 1; j < rings; ++j) {
    const double scale = 1.0 - static_cast<double>(j) / rings;
    // Halve the directions when the ring's edges would be under half the loop's.
    std::vector<size_t> halved;
    if (scale * perimeter_mm / static_cast<double>(directions.size()) < 0.5 * edge_mm && directions.size() >= 6)
      for (size_t i = 0; i < directions.size(); i += 2) halved.push_back(directions[i]);
    bool placed = false;
    for (const std::vector<size_t>* along : {&halved, &directions}) {
      if (along->empty()) continue;
      Ring inner;
      const size_t first_vertex = vertices.size();
      for (size_t k : *along) {
        inner.point.push_back(scale * loop_points[k]);
        inner.fraction.push_back(loop_fractions[k]);
        inner.vertex.push_back(first_new_index + static_cast<int>(first_vertex + inner.vertex.size()));
      }
      if (!zip_rings(outer, inner, turns.sign, smallest_area_mm2, faces)) continue;
      for (const Eigen::Vector2d& p : inner.point) {
        vertices.push_back((plane.centroid + p.x() * plane.u + p.y() * plane.v).transpose());
        normals.push_back(plane.normal);
      }
      directions = *along;
      outer = std::move(inner);
      placed = true;
      break;
    }
    if (!placed) {  // not expected for a star-shaped loop (trapezoids): undo, the caller falls back to a fan
      vertices.resize(vertices_before), faces.resize(faces_before), normals.resize(normals_before);
      return false;
    }
  }
  if (outer.vertex.size() == 3 && rings == 1) {
    faces.emplace_back(outer.vertex[2], outer.vertex[1], outer.vertex[0]);
    return true;
  }
  vertices.push_back(plane.centroid.transpose());
  normals.push_back(plane.normal);
  const int centre = first_new_index + static_cast<int>(vertices.size()) - 1;
  for (size_t i = 0; i < outer.vertex.size(); ++i)
    faces.emplace_back(outer.vertex[(i + 1) % outer.vertex.size()], outer.vertex[i], centre);
  return true;
}

// The fallback for a loop that is not star-shaped: a fan around its centroid (fairing then lifts the
// centre onto the surface).
void fan_patch(const Eigen::MatrixXd& V, const std::vector<int>& loop, int first_new_index,
               std::vector<Eigen::RowVector3d>& vertices, std::vector<Eigen::RowVector3i>& faces,
               std::vector<Eigen::Vector3d>& normals) {
  const LoopPlane plane = loop_plane(V, loop);
  vertices.push_back(plane.centroid.transpose());
  normals.push_back(plane.normal);
  const int centre = first_new_index + static_cast<int>(vertices.size()) - 1;
  for (size_t i = 0; i < loop.size(); ++i) faces.emplace_back(loop[(i + 1) % loop.size()], loop[i], centre);
}

}  // namespace

double loop_across_mm(const Eigen::MatrixXd& V, const std::vector<int>& loop) {
  double largest_squared = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i)
    for (std::size_t j = i + 1; j < loop.size(); ++j)
      largest_squared = std::max(largest_squared, (V.row(loop[i]) - V.row(loop[j])).squaredNorm());
  return std::sqrt(largest_squared);
}

std::vector<HoleRepair> fill_holes(TriMesh& mesh, double max_across_mm) {
  MeshTopology topology = build_mesh_topology(mesh.F, mesh.V.rows());
  return fill_holes(mesh, topology, max_across_mm);
}

std::vector<HoleRepair> fill_holes(TriMesh& mesh, MeshTopology& topology, double max_across_mm) {
  if (topology.vertex_count() != mesh.V.rows() || topology.face_count() != mesh.F.rows())
    throw EngineError("hole filling: the mesh topology was built for another mesh");
  // The holes to close, and their sizes as the scan had them (trimming widens them a little).
  constexpr std::size_t kLargestLoopChecked = 4000;  // a loop this long is an opening, not a scan hole
  std::vector<HoleRepair> repairs;
  std::vector<int> hole_of_vertex(static_cast<size_t>(mesh.V.rows()), -1);
  for (const std::vector<int>& loop : topology.boundary_loops) {
    if (loop.size() < 3 || loop.size() > kLargestLoopChecked) continue;
    const double across_mm = loop_across_mm(mesh.V, loop);
    if (across_mm > max_across_mm) continue;
    for (int v : loop) hole_of_vertex[static_cast<size_t>(v)] = static_cast<int>(repairs.size());
    repairs.push_back({across_mm, 0, false});
  }
  if (repairs.empty()) return {};
  trim_holes_to_star_shapes(mesh, topology, hole_of_vertex);
  // The loops run along the faces' own edges; at a pinch a loop takes whichever boundary edge comes first.
  const std::vector<std::vector<int>>& loops = topology.boundary_loops;  // read before the patches change it
  std::vector<Eigen::RowVector3d> new_vertices;
  std::vector<Eigen::RowVector3i> new_faces;
  std::vector<Eigen::Vector3d> new_normals;  // per new vertex: its hole's plane normal (it moves only along it)
  for (const std::vector<int>& loop : loops) {
    const int hole = hole_of_loop(loop, hole_of_vertex);
    if (hole < 0) continue;  // a loop larger than the limit: left open
    HoleRepair& repair = repairs[static_cast<size_t>(hole)];
    const size_t vertices_before = new_vertices.size();
    if (loop.size() == 3) {
      new_faces.emplace_back(loop[2], loop[1], loop[0]);
    } else if (!ring_patch(mesh.V, loop, static_cast<int>(mesh.V.rows()), new_vertices, new_faces, new_normals)) {
      fan_patch(mesh.V, loop, static_cast<int>(mesh.V.rows()), new_vertices, new_faces, new_normals);
      repair.fan = true;
    }
    repair.patch_vertices += static_cast<int>(new_vertices.size() - vertices_before);
  }
  const Eigen::Index old_v = mesh.V.rows(), old_f = mesh.F.rows();
  mesh.V.conservativeResize(old_v + static_cast<Eigen::Index>(new_vertices.size()), 3);
  for (std::size_t i = 0; i < new_vertices.size(); ++i) mesh.V.row(old_v + static_cast<Eigen::Index>(i)) = new_vertices[i];
  mesh.F.conservativeResize(old_f + static_cast<Eigen::Index>(new_faces.size()), 3);
  for (std::size_t i = 0; i < new_faces.size(); ++i) mesh.F.row(old_f + static_cast<Eigen::Index>(i)) = new_faces[i];
  std::vector<int> patch_vertices(new_vertices.size());
  for (std::size_t i = 0; i < new_vertices.size(); ++i) patch_vertices[i] = static_cast<int>(old_v) + static_cast<int>(i);
  // The patches add faces: the closed mesh's topology, for the fairing (which moves vertices only)
  // and for the caller.
  if (!new_faces.empty()) topology = build_mesh_topology(mesh.F, mesh.V.rows());
  fair_vertices_bilaplacian(mesh, topology, patch_vertices, new_normals);
  return repairs;
}

}  // namespace lastcut
