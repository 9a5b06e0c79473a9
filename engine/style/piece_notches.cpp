// Notches on a style's pieces; see piece_notches.hpp.
#include "engine/style/piece_notches.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "engine/core/polyline_3d.hpp"
#include "engine/mold/notch_placement.hpp"

namespace lastcut {
namespace {

std::string seam_name(PieceEdgeSource::Kind kind) { return kind == PieceEdgeSource::Kind::FrontSeam ? "front seam" : "back seam"; }

bool near_any(const Eigen::Vector3d& p, const std::vector<NotchPoint>& points, double within_mm) {
  for (const NotchPoint& point : points)
    if ((point.position_mm - p).norm() < within_mm) return true;
  return false;
}

// The closest point of a piece's outline to p: which stretch, the outline edge (as its two vertices)
// and where along it.
struct OutlineHit {
  double distance_mm = INFINITY;
  const PieceMoldEdge* stretch = nullptr;
  int from = -1, to = -1;  // mesh vertices, in outline order (CCW in UV)
  double t = 0;
};

OutlineHit closest_on_outline(const Eigen::Vector3d& p, const TriMesh& mesh, const std::vector<PieceMoldEdge>& stretches) {
  OutlineHit best;
  for (const PieceMoldEdge& stretch : stretches)
    for (std::size_t i = 1; i < stretch.outline_vertices.size(); ++i) {
      const int a = stretch.outline_vertices[i - 1], b = stretch.outline_vertices[i];
      const Eigen::Vector3d pa = mesh.V.row(a).transpose(), ab = mesh.V.row(b).transpose() - pa;
      const double t = std::clamp((p - pa).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
      const double distance = (pa + t * ab - p).norm();
      if (distance < best.distance_mm) best = {distance, &stretch, a, b, t};
    }
  return best;
}

bool at_corner(const Eigen::Vector3d& p, const TriMesh& mesh, const PieceMoldEdge& stretch) {
  return (mesh.V.row(stretch.outline_vertices.front()).transpose() - p).norm() < kOnPieceOutline_mm ||
         (mesh.V.row(stretch.outline_vertices.back()).transpose() - p).norm() < kOnPieceOutline_mm;
}

}  // namespace

std::vector<SewnCurve> sewn_curves(const PieceEdgeCurves& curves, const std::vector<std::string>& line_names) {
  std::vector<SewnCurve> sewn;
  bool front_seen = false, back_seen = false;
  std::map<int, int> runs_of_line;
  for (const auto& [source, points] : curves.curves) {
    switch (source.kind) {
      case PieceEdgeSource::Kind::Line: {
        // A line that leaves the upper and comes back is sewn in parts: NAME, NAME (2), ... (as `style transfer` writes them)
        const int run = ++runs_of_line[source.line];
        const std::string& name = line_names.at(static_cast<std::size_t>(source.line));
        sewn.push_back({source, run == 1 ? name : name + " (" + std::to_string(run) + ")", points});
        break;
      }
      case PieceEdgeSource::Kind::FrontSeam:
      case PieceEdgeSource::Kind::BackSeam: {
        bool& seen = source.kind == PieceEdgeSource::Kind::FrontSeam ? front_seen : back_seen;
        if (!seen) sewn.push_back({source, seam_name(source.kind), points});
        seen = true;
        break;
      }
      case PieceEdgeSource::Kind::Feather:
      case PieceEdgeSource::Kind::Top: break;
    }
  }
  return sewn;
}

std::vector<NotchPoint> line_junctions(const std::vector<TransferredCurve>& lines, const std::vector<std::string>& line_names,
                                       const Eigen::Affine3d& scan_to_canonical) {
  std::vector<NotchPoint> junctions;
  const auto add = [&](const std::string& name, const Eigen::Vector3d& at) {
    if (!near_any(at, junctions, kOnPieceOutline_mm)) junctions.push_back({name, at, 0, false});
  };
  std::vector<std::vector<Polyline3>> runs(lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i) {
    runs[i] = runs_on_upper(lines[i]);
    for (Polyline3& run : runs[i])
      for (Eigen::Vector3d& point : run) point = scan_to_canonical * point;
    for (const TransferredPoint& point : lines[i].points)
      if (point.on_outline && (point.edge == EdgeKind::FrontSeam || point.edge == EdgeKind::BackSeam))
        add(line_names.at(i) + " x " + (point.edge == EdgeKind::FrontSeam ? "front seam" : "back seam"),
            scan_to_canonical * point.position_mm);
  }
  // A run that ends inside the upper ends on another line (a T-junction).
  for (std::size_t i = 0; i < lines.size(); ++i)
    for (const Polyline3& run : runs[i])
      for (const Eigen::Vector3d& end : {run.front(), run.back()})
        for (std::size_t j = 0; j < lines.size(); ++j)
          for (const Polyline3& other : runs[j])
            if (j != i && closest_on_polyline(end, other).distance_mm < kOnPieceOutline_mm)
              add(line_names.at(i) + " x " + line_names.at(j), end);
  return junctions;
}

std::vector<NotchPoint> seam_notch_points(const std::vector<SewnCurve>& curves, const std::vector<NotchPoint>& junctions,
                                          double spacing_mm) {
  std::vector<NotchPoint> points = junctions;
  for (const SewnCurve& curve : curves) {
    const double length_mm = polyline_length_mm(curve.points_mm);
    std::vector<double> junction_arcs;  // of the junctions on this curve
    for (const NotchPoint& junction : junctions)
      if (const PolylineHit hit = closest_on_polyline(junction.position_mm, curve.points_mm); hit.distance_mm < kOnPieceOutline_mm)
        junction_arcs.push_back(hit.arc_length_mm);
    for (int k = 1; k * spacing_mm <= length_mm - spacing_mm / 2; ++k) {
      const double s_mm = k * spacing_mm;
      const bool beside_junction = std::any_of(junction_arcs.begin(), junction_arcs.end(),
                                               [&](double arc) { return std::abs(arc - s_mm) < spacing_mm / 2; });
      if (!beside_junction)
        points.push_back({curve.name + " " + std::to_string(k), point_at_arc_length(curve.points_mm, s_mm), s_mm, true});
    }
  }
  return points;
}

std::vector<PieceNotch> place_piece_notches(const PieceSurface& surface, const std::vector<NotchPoint>& points, PieceMold& mold) {
  std::vector<PieceNotch> placed;
  for (const NotchPoint& point : points) {
    const OutlineHit hit = closest_on_outline(point.position_mm, surface.mesh, mold.edges);
    if (hit.distance_mm > kOnPieceOutline_mm) continue;  // not on this piece's outline
    if (!point.balance && at_corner(point.position_mm, surface.mesh, *hit.stretch)) continue;  // the corner marks it
    const Point2 a = mold.UV.row(hit.from).transpose(), b = mold.UV.row(hit.to).transpose();
    const Point2 net_point = a + hit.t * (b - a);
    const Point2 along = (b - a).normalized();
    const Point2 outward(along.y(), -along.x());  // the outline runs counter-clockwise
    mold.mold.marks.push_back(notch_along_normal(point.name, mold.mold.outline, net_point, outward));
    placed.push_back({point.name, net_point, point.arc_length_mm, point.balance});
  }
  return placed;
}

}  // namespace lastcut
