#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>

#include "engine/core/engine_error.hpp"
#include "engine/mold/boundary_loops.hpp"
#include "engine/mold/clipper_paths.hpp"
#include "engine/mold/mold.hpp"
#include "engine/mold/notch_placement.hpp"
#include "engine/mold/outline_geometry.hpp"
#include "engine/mold/outline_simplify.hpp"

namespace lastcut {

namespace {

std::string format_point(const Point2& p) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.1f, %.1f) mm", p.x(), p.y());
  return text;
}

void check_inputs(const std::string& name, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F,
                  const MoldOptions& options) {
  if (!(options.allowance_mm >= 0.0) || !std::isfinite(options.allowance_mm))
    throw EngineError("allowance must be a finite number of millimetres >= 0");
  if (options.edge_allowances && options.allowance_mm > 0.0)
    throw EngineError("give one allowance for all edges or per-edge allowances, not both");
  if (!(options.simplify_tolerance_mm >= 0.0) || !std::isfinite(options.simplify_tolerance_mm))
    throw EngineError("simplification tolerance must be a finite number of millimetres >= 0");
  if (UV.cols() != 2) throw EngineError("mold " + name + ": flattened positions must have 2 columns");
  if (F.rows() == 0 || F.cols() != 3) throw EngineError("mold " + name + ": no triangles to make a mold from");
  if (F.minCoeff() < 0 || F.maxCoeff() >= UV.rows())
    throw EngineError("mold " + name + ": a triangle refers to a vertex that does not exist");
  if (!UV.allFinite()) throw EngineError("mold " + name + ": flattened positions contain NaN or infinity");
}

double loop_length(const Eigen::MatrixXd& UV, const std::vector<int>& loop) {
  double length = 0.0;
  for (size_t i = 0; i < loop.size(); ++i)
    length += (UV.row(loop[(i + 1) % loop.size()]) - UV.row(loop[i])).norm();
  return length;
}

Polygon2 offset_outward(const Polygon2& outline, double allowance_mm, double tolerance_mm) {
  // Half the tolerance: Clipper's chords of the round joins then stay well within it.
  ClipperLib::ClipperOffset offset(2.0, std::max(0.5 * tolerance_mm, 0.001) * kClipperUnitsPerMm);
  offset.AddPath(to_clipper_path(outline.points), ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  ClipperLib::Paths solution;
  offset.Execute(solution, allowance_mm * kClipperUnitsPerMm);
  // Growing a simple polygon gives one outer ring (and possibly holes where narrow bays close).
  const ClipperLib::Path* outer = largest_ring(solution);
  if (outer == nullptr) throw EngineError("allowance offset produced no outline");
  Polygon2 grown = from_clipper_path(*outer);
  make_counter_clockwise(grown);
  return grown;
}

}  // namespace

Mold make_mold(std::string name, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F,
               const std::map<std::string, int>& landmark_vertices, const MoldOptions& options) {
  check_inputs(name, UV, F, options);
  return make_mold(std::move(name), UV, F, landmark_vertices, options, build_mesh_topology(F, UV.rows()));
}

Mold make_mold(std::string name, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F,
               const std::map<std::string, int>& landmark_vertices, const MoldOptions& options,
               const MeshTopology& topology) {
  check_inputs(name, UV, F, options);
  if (topology.vertex_count() != UV.rows() || topology.face_count() != F.rows())
    throw EngineError("mold " + name + ": the mesh topology was built for another patch");
  const auto loops = simple_boundary_loops(topology);
  if (loops.empty()) throw EngineError("mold " + name + ": the patch is closed; it has no outline to cut");
  const auto longest = std::max_element(loops.begin(), loops.end(), [&](const auto& a, const auto& b) {
    return loop_length(UV, a) < loop_length(UV, b);
  });

  // Outline through the loop's vertices; drop exact repeats (zero-length edges).
  Polygon2 boundary;
  std::vector<int> boundary_vertex;
  for (int v : *longest) {
    const Point2 p = UV.row(v).transpose();
    if (!boundary.points.empty() && p == boundary.points.back()) continue;
    boundary.points.push_back(p);
    boundary_vertex.push_back(v);
  }
  while (boundary.points.size() > 1 && boundary.points.front() == boundary.points.back()) {
    boundary.points.pop_back();
    boundary_vertex.pop_back();
  }
  if (boundary.points.size() < 3 || std::abs(signed_area(boundary)) == 0.0)
    throw EngineError("mold " + name + ": the flattened outline has no area");
  if (signed_area(boundary) < 0.0) {
    std::reverse(boundary.points.begin(), boundary.points.end());
    std::reverse(boundary_vertex.begin(), boundary_vertex.end());
  }
  if (const auto crossing = find_self_intersection(boundary))
    throw EngineError("mold " + name + ": the flattened outline overlaps itself near " +
                      format_point(boundary.points[crossing->first]) + "; it cannot be cut as one piece");

  std::unordered_map<int, int> position_in_boundary;
  for (int i = 0; i < static_cast<int>(boundary_vertex.size()); ++i) position_in_boundary[boundary_vertex[i]] = i;
  std::vector<int> keep;
  std::vector<std::pair<std::string, int>> landmark_at;  // name, index in the boundary
  for (const auto& [landmark, vertex] : landmark_vertices) {
    if (vertex < 0 || vertex >= UV.rows())
      throw EngineError("mold " + name + ": landmark " + landmark + " refers to vertex " + std::to_string(vertex) +
                        " of a patch with " + std::to_string(UV.rows()) + " vertices");
    if (const auto found = position_in_boundary.find(vertex); found != position_in_boundary.end()) {
      keep.push_back(found->second);
      landmark_at.emplace_back(landmark, found->second);
    }
  }

  Mold mold;
  mold.name = std::move(name);
  const std::vector<int> kept = simplify_outline(boundary, options.simplify_tolerance_mm, keep);
  mold.outline = select_points(boundary, kept);
  const bool balance = options.balance_notches.seam_spacing_mm != 0.0 || options.balance_notches.feather_spacing_mm != 0.0;
  std::vector<NetEdge> edges;
  if (options.edge_allowances || balance) {
    for (auto& [landmark, index] : landmark_at)
      index = static_cast<int>(std::lower_bound(kept.begin(), kept.end(), index) - kept.begin());
    try {
      edges = split_net_edges(mold.outline, landmark_at);
    } catch (const EngineError& error) {
      throw EngineError("mold " + mold.name + ": " + error.what());
    }
  }
  const Polygon2 net = mold.outline;
  const auto& per_edge = options.edge_allowances;
  if (per_edge && (per_edge->lasting_mm != 0.0 || per_edge->seam_mm != 0.0 || per_edge->top_mm != 0.0))
    mold.outline = grow_by_edge_allowances(net, edges, *options.edge_allowances, std::max(options.simplify_tolerance_mm, 0.002));
  else if (options.allowance_mm > 0.0)
    mold.outline = offset_outward(net, options.allowance_mm, options.simplify_tolerance_mm);
  if (mold.outline.points != net.points) mold.net = net;
  for (const auto& [landmark, vertex] : landmark_vertices)
    mold.marks.push_back(notch_at(landmark, mold.outline, UV.row(vertex).transpose()));
  for (const NetNotch& notch : balance_notch_points(edges, options.balance_notches))
    mold.marks.push_back(notch_along_normal(notch.name, mold.outline, notch.position_mm, notch.outward_normal));
  return mold;
}

}  // namespace lastcut
