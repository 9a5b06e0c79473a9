// Seam lengths on both sides; see seam_report.hpp.
#include "engine/style/seam_report.hpp"

#include <algorithm>

#include "engine/core/polyline_3d.hpp"

namespace lastcut {
namespace {

double net_length_mm(const PieceMoldEdge& edge) {
  double length = 0;
  for (std::size_t i = 1; i < edge.net_points.size(); ++i) length += (edge.net_points[i] - edge.net_points[i - 1]).norm();
  return length;
}

void add_piece(std::vector<std::string>& names, const std::string& name) {
  if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
}

}  // namespace

std::vector<SeamReport> seam_reports(const std::vector<SewnCurve>& curves,
                                     const std::vector<std::pair<const PieceSurface*, const PieceMold*>>& pieces) {
  std::vector<SeamReport> reports;
  for (const SewnCurve& curve : curves) {
    SeamReport report{curve.name, {}, {}, 0, 0, 0};
    for (const auto& piece : pieces) {
      const PieceSurface* surface = piece.first;  // not a structured binding: the lambda below captures it
      for (const PieceMoldEdge& edge : piece.second->edges) {
        if (!(edge.source == curve.source) || edge.outline_vertices.size() < 2) continue;
        const auto vertex = [&](std::size_t i) { return Eigen::Vector3d(surface->mesh.V.row(edge.outline_vertices[i]).transpose()); };
        const PolylineHit middle = closest_on_polyline(vertex(edge.outline_vertices.size() / 2), curve.points_mm);
        if (middle.distance_mm > kOnPieceOutline_mm) continue;  // along another run of the same line
        const bool forward = closest_on_polyline(vertex(edge.outline_vertices.size() - 1), curve.points_mm).arc_length_mm >
                             closest_on_polyline(vertex(0), curve.points_mm).arc_length_mm;
        if (forward) {
          add_piece(report.one_side, surface->name);
          report.one_side_mm += net_length_mm(edge);
          report.length_3d_mm += edge.length_3d_mm;
        } else {
          add_piece(report.other_side, surface->name);
          report.other_side_mm += net_length_mm(edge);
        }
      }
    }
    if (!report.one_side.empty() && !report.other_side.empty()) reports.push_back(std::move(report));
  }
  return reports;
}

}  // namespace lastcut
