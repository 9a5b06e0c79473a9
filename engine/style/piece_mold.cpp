#include "engine/style/piece_mold.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/engine_error.hpp"
#include "engine/core/polyline_3d.hpp"
#include "engine/flatten/arap_held_lengths.hpp"
#include "engine/flatten/disk_topology.hpp"
#include "engine/mold/outer_hull_chain.hpp"
#include "engine/mold/outward_allowance.hpp"
#include "engine/mold/outline_geometry.hpp"
#include "engine/mold/outline_simplify.hpp"
#include "engine/style/forme_boundary.hpp"
#include "engine/style/piece_thickness.hpp"

namespace lastcut {
namespace {

double distance_to_curve(const Eigen::Vector3d& p, const Polyline3& curve) { return closest_on_polyline(p, curve).distance_mm; }

PieceEdgeSource::Kind kind_of(EdgeKind kind) {
  switch (kind) {
    case EdgeKind::Feather: return PieceEdgeSource::Kind::Feather;
    case EdgeKind::Top: return PieceEdgeSource::Kind::Top;
    case EdgeKind::FrontSeam: return PieceEdgeSource::Kind::FrontSeam;
    case EdgeKind::BackSeam: return PieceEdgeSource::Kind::BackSeam;
  }
  return PieceEdgeSource::Kind::Feather;
}


// Two curves this close to a point are as near as each other: the point is a corner of both.
constexpr double kSameDistance_mm = 0.01;

// Whether p lies on a curve of `source`.
bool lies_on(const Eigen::Vector3d& p, const PieceEdgeSource& source, const PieceEdgeCurves& curves) {
  for (const auto& [candidate, curve] : curves.curves)
    if (candidate == source && distance_to_curve(p, curve) <= kSameDistance_mm) return true;
  return false;
}

// What each vertex of the outline `loop` lies on: the nearest of the curves; a line when it is as near, and
// the feather line or top edge rather than a centre seam.
std::vector<PieceEdgeSource> outline_sources(const TriMesh& mesh, const std::vector<int>& loop, const PieceEdgeCurves& curves) {
  std::vector<PieceEdgeSource> source(loop.size());
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector3d p = mesh.V.row(loop[i]).transpose();
    double nearest = INFINITY, nearest_line = INFINITY;
    PieceEdgeSource line;
    for (const auto& [candidate, curve] : curves.curves) {
      const double distance = distance_to_curve(p, curve);
      if (distance < nearest) nearest = distance, source[i] = candidate;
      if (candidate.kind == PieceEdgeSource::Kind::Line && distance < nearest_line) nearest_line = distance, line = candidate;
    }
    if (nearest_line <= nearest + kSameDistance_mm) {
      source[i] = line;
      continue;
    }
    // Where a centre seam ends on the feather line or the top edge, the end is the edge's: an uncut seam
    // runs inside its piece, and a stretch of it on the outline would be a slit through the margin.
    if (source[i].kind == PieceEdgeSource::Kind::FrontSeam || source[i].kind == PieceEdgeSource::Kind::BackSeam)
      for (const auto& [candidate, curve] : curves.curves)
        if ((candidate.kind == PieceEdgeSource::Kind::Feather || candidate.kind == PieceEdgeSource::Kind::Top) &&
            distance_to_curve(p, curve) <= nearest + kSameDistance_mm) {
          source[i] = candidate;
          break;
        }
  }
  return source;
}

// The piece's flattening with its sewn outline edges held at their 3D length (arap_held_lengths.hpp), so
// the two pieces of every seam have the seam's length. Its steps never fold a triangle.
void hold_sewn_lengths(const TriMesh& surface, const MeshTopology& topology, const std::vector<int>& loop,
                       const std::vector<PieceEdgeSource>& source, PieceMold& result) {
  std::vector<std::array<int, 2>> held;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const std::size_t next = (i + 1) % loop.size();
    if (is_sewn(source[i]) && is_sewn(source[next])) held.push_back({loop[i], loop[next]});
  }
  if (held.empty()) return;
  const HeldLengthReport report = hold_edge_lengths(surface, topology, held, result.UV);
  result.flatten.notes.push_back("sewn edges held at their 3D length (" + std::to_string(held.size()) + " edges, " +
                                 std::to_string(report.iterations) + " iterations" +
                                 (report.shortened_steps > 0 ? ", " + std::to_string(report.shortened_steps) + " steps shortened against folds" : "") +
                                 (report.stalled_on_flips ? ", stopped where a step would fold a triangle" : "") + ")");
}
}  // namespace

bool is_sewn(const PieceEdgeSource& source) {
  return source.kind == PieceEdgeSource::Kind::Line || source.kind == PieceEdgeSource::Kind::FrontSeam ||
         source.kind == PieceEdgeSource::Kind::BackSeam;
}

std::string to_string(const PieceEdgeSource& source, const std::vector<std::string>& line_names) {
  switch (source.kind) {
    case PieceEdgeSource::Kind::Feather: return "feather line";
    case PieceEdgeSource::Kind::Top: return "top edge";
    case PieceEdgeSource::Kind::FrontSeam: return "front seam";
    case PieceEdgeSource::Kind::BackSeam: return "back seam";
    case PieceEdgeSource::Kind::Line:
      return source.line >= 0 && static_cast<std::size_t>(source.line) < line_names.size()
                 ? "line " + line_names[static_cast<std::size_t>(source.line)]
                 : "line " + std::to_string(source.line);
  }
  return "?";
}

PieceEdgeCurves piece_edge_curves(const std::array<const SegmentResult*, 2>& halves, const std::vector<TransferredCurve>& lines,
                                  const Eigen::Affine3d& scan_to_canonical) {
  PieceEdgeCurves curves;
  for (const SegmentResult* half : halves) {
    const FormeBoundary boundary = forme_boundary(half->mesh3d, half->topology, half->landmarks);
    for (const FormeEdge& edge : boundary.edges) {
      std::vector<Eigen::Vector3d> points;
      for (const int v : edge.vertices) points.push_back(half->mesh3d.V.row(v).transpose());
      curves.curves.emplace_back(PieceEdgeSource{kind_of(edge.kind), -1}, std::move(points));
    }
  }
  // A line in its runs on the upper: a chord across the sole would pass next to the feather line there.
  for (std::size_t i = 0; i < lines.size(); ++i)
    for (std::vector<Eigen::Vector3d>& run : runs_on_upper(lines[i])) {
      for (Eigen::Vector3d& point : run) point = scan_to_canonical * point;
      curves.curves.emplace_back(PieceEdgeSource{PieceEdgeSource::Kind::Line, static_cast<int>(i)}, std::move(run));
    }
  return curves;
}

PieceMold make_piece_mold(const PieceSurface& piece, const PieceEdgeCurves& curves, const AllowanceRule& allowance_of,
                          const PieceMoldOptions& options) {
  PieceMold result;
  const MeshTopology topology = build_mesh_topology(piece.mesh.F, piece.mesh.V.rows());
  if (topology.boundary_loops.size() != 1)
    throw EngineError("piece " + piece.name + " is not one patch with one outline (" +
                      std::to_string(topology.boundary_loops.size()) + " outlines): check the style's lines around it");
  check_disk(piece.mesh, topology);
  // What each outline vertex lies on in 3D. A corner where a line meets an edge or crosses a seam lies on
  // both: it goes with the line, so a seam crossing does not become a stretch of its own.
  std::vector<int> loop = topology.boundary_loops.front();
  std::vector<PieceEdgeSource> source = outline_sources(piece.mesh, loop, curves);

  // The lengths the leather must have: the last's, or its mid-surface's for a piece with a thickness.
  TriMesh offset;
  if (options.surface_offset_mm > 0) offset = offset_along_normals(piece.mesh, options.surface_offset_mm);
  const TriMesh& surface = options.surface_offset_mm > 0 ? offset : piece.mesh;
  result.flatten = flatten(surface, topology, options.flatten);
  result.UV = result.flatten.UV;
  if (options.hold_sewn_lengths) hold_sewn_lengths(surface, topology, loop, source, result);
  result.measures = measure_distortion(surface, result.UV, topology);

  // The outline in the flattening, counter-clockwise.
  Polygon2 net;
  for (const int v : loop) net.points.push_back(result.UV.row(v).transpose());
  if (signed_area(net) < 0) {
    std::reverse(loop.begin(), loop.end());
    std::reverse(source.begin(), source.end());
    std::reverse(net.points.begin(), net.points.end());
  }
  if (!is_simple(net)) throw EngineError("piece " + piece.name + ": the flattened outline overlaps itself");
  // Stretches of one source, starting where the source changes (a piece cut by nothing but one
  // closed line has a single stretch, from vertex 0). Two stretches share their corner, which lies on
  // both and was told to one of them: where the vertex before the change lies on the next stretch's
  // curve too, the next stretch starts there, so the edges from the corner on count for the same stretch
  // on every piece, whichever way the piece's outline runs.
  const std::size_t n = loop.size();
  std::size_t start = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (!(source[i] == source[(i + n - 1) % n])) {
      start = i;
      break;
    }
  std::vector<int> stretch_starts;
  std::vector<PieceEdgeSource> stretch_source;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (start + k) % n, before = (i + n - 1) % n;
    if (k > 0 && source[i] == source[before]) continue;
    const int corner = static_cast<int>(lies_on(piece.mesh.V.row(loop[before]).transpose(), source[i], curves) ? before : i);
    if (!stretch_starts.empty() && stretch_starts.back() == corner) {  // a line stretch of its corner alone
      stretch_starts.pop_back();
      stretch_source.pop_back();
    }
    if (!stretch_source.empty() && stretch_source.back() == source[i]) continue;  // then the stretch before goes on
    stretch_starts.push_back(corner);
    stretch_source.push_back(source[i]);
  }
  if (stretch_source.size() > 1 && stretch_source.back() == stretch_source.front()) {  // the last goes on into the first
    stretch_starts.erase(stretch_starts.begin());
    stretch_source.erase(stretch_source.begin());
  }
  // Each stretch's length on the surface flattened, from its start to the next stretch's.
  std::vector<double> length_3d(stretch_starts.size(), 0.0);
  for (std::size_t s = 0; s < stretch_starts.size(); ++s) {
    const std::size_t from = static_cast<std::size_t>(stretch_starts[s]);
    const std::size_t to = static_cast<std::size_t>(stretch_starts[(s + 1) % stretch_starts.size()]);
    std::size_t i = from;
    do {  // a single stretch (from == to) goes once round
      length_3d[s] += (surface.V.row(loop[(i + 1) % n]) - surface.V.row(loop[i])).norm();
      i = (i + 1) % n;
    } while (i != to);
  }
  const std::vector<int> kept = simplify_outline(net, kPieceSimplifyTolerance_mm, stretch_starts);
  const Polygon2 simple = select_points(net, kept);
  // Kept indices are increasing; walk them from the first stretch start round the loop.
  const std::size_t first = static_cast<std::size_t>(std::find(kept.begin(), kept.end(), stretch_starts.front()) - kept.begin());
  std::vector<AllowanceEdge> grown;
  for (std::size_t k = 0; k <= kept.size(); ++k) {
    const std::size_t at = (first + k) % kept.size();
    const int vertex = kept[at];
    const bool starts = std::find(stretch_starts.begin(), stretch_starts.end(), vertex) != stretch_starts.end();
    if (!result.edges.empty()) result.edges.back().net_points.push_back(simple.points[at]);
    if (starts && k < kept.size()) {
      const std::size_t stretch = static_cast<std::size_t>(
          std::find(stretch_starts.begin(), stretch_starts.end(), vertex) - stretch_starts.begin());
      const PieceEdgeSource& what = stretch_source[stretch];
      result.edges.push_back({what, allowance_of(what), {simple.points[at]}, length_3d[stretch]});
    }
  }
  for (std::size_t e = 0; e < result.edges.size(); ++e) {  // edges[e] is stretch e
    const std::size_t to = static_cast<std::size_t>(stretch_starts[(e + 1) % stretch_starts.size()]);
    std::size_t i = static_cast<std::size_t>(stretch_starts[e]);
    do {
      result.edges[e].outline_vertices.push_back(loop[i]);
      i = (i + 1) % n;
    } while (i != to);
    result.edges[e].outline_vertices.push_back(loop[to]);
  }
  // The outline the allowances grow from: the net, with an extension's dents bridged (kTopExtensionAbove_mm).
  Polygon2 grown_from;
  for (const PieceMoldEdge& edge : result.edges) {
    const bool extension = edge.source.kind == PieceEdgeSource::Kind::Top && edge.allowance_mm > kTopExtensionAbove_mm;
    grown.push_back({extension ? outer_hull_chain(edge.net_points) : edge.net_points, edge.allowance_mm});
    grown_from.points.insert(grown_from.points.end(), grown.back().points.begin(), grown.back().points.end() - 1);
  }
  result.mold.name = piece.name;
  result.mold.net = simple;
  result.mold.outline = grow_outward_by_allowances(grown_from, grown, kPieceSimplifyTolerance_mm);
  return result;
}

}  // namespace lastcut
