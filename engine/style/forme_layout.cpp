#include "engine/style/forme_layout.hpp"

#include <cmath>
#include <numbers>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

constexpr double kCentreSampleSpacing_mm = 1.0;  // about one centre-line sample per millimetre of seam
constexpr int kMinCentreSamples = 8;             // per seam, however short

const SegmentResult& layout_half(const ScanResult& reference, const char* name) {
  for (const SegmentResult& segment : reference.segments)
    if (segment.name == name) return segment;
  throw EngineError(std::string("the reference last has no ") + name +
                    " half: a forme needs a last segmented with its side named (--side left or right)");
}

// The point of the half's flattening (not yet laid on the forme) at `share` of an outline edge.
Point2 uv_at_share(const SegmentResult& half, const FormeEdge& edge, double share) {
  const EdgeSpot spot = spot_at_share(edge, share);
  return (1 - spot.weight_b) * half.UV.row(spot.a).transpose() + spot.weight_b * half.UV.row(spot.b).transpose();
}

}  // namespace

Point2 FormeHalfLayout::to_forme(const Point2& uv_mm) const {
  const Point2 flipped(uv_mm.x(), mirrored ? -uv_mm.y() : uv_mm.y());
  return rotation * flipped + translation;
}

std::vector<Point2> FormeHalfLayout::edge_points(EdgeKind kind) const {
  std::vector<Point2> points;
  for (const int v : boundary.edge(kind).vertices) points.push_back(forme_uv_mm.row(v).transpose());
  return points;
}

std::vector<Point2> FormeHalfLayout::outline() const {
  std::vector<Point2> points;
  for (const int v : segment->topology.boundary_loops.front()) points.push_back(forme_uv_mm.row(v).transpose());
  return points;
}

Point2 FormeHalfLayout::landmark(const std::string& name) const {
  return forme_uv_mm.row(segment->landmarks.at(name)).transpose();
}

double FormeHalfLayout::edge_length_mm(EdgeKind kind) const {
  const std::vector<int>& vertices = boundary.edge(kind).vertices;
  double length_mm = 0;
  for (std::size_t i = 1; i < vertices.size(); ++i)
    length_mm += (segment->mesh3d.V.row(vertices[i]) - segment->mesh3d.V.row(vertices[i - 1])).norm();
  return length_mm;
}

Eigen::Vector3d FormeHalfLayout::edge_point_3d(EdgeKind kind, double share) const {
  const EdgeSpot spot = spot_at_share(boundary.edge(kind), share);
  return (1 - spot.weight_b) * segment->mesh3d.V.row(spot.a).transpose() + spot.weight_b * segment->mesh3d.V.row(spot.b).transpose();
}

FormeLayout forme_layout(const ScanResult& reference) {
  FormeLayout layout;
  const std::array<const char*, 2> names = {"medial", "lateral"};
  for (std::size_t h = 0; h < 2; ++h) {
    const SegmentResult& half = layout_half(reference, names[h]);
    FormeHalfLayout& laid = layout.halves[h];
    laid.segment = &half;
    try {
      laid.boundary = forme_boundary(half.mesh3d, half.topology, half.landmarks);
    } catch (const EngineError& error) {
      throw EngineError(std::string("the reference last's ") + names[h] + " half: " + error.what());
    }
    laid.mirrored = h == 0;
  }
  // Pairs of centre-line points, medial (mirrored, not yet moved) and lateral, at equal shares of each seam.
  FormeHalfLayout& medial = layout.halves[0];
  const FormeHalfLayout& lateral = layout.halves[1];
  std::vector<Point2> from, to;
  for (const EdgeKind seam : {EdgeKind::FrontSeam, EdgeKind::BackSeam}) {
    const FormeEdge& lateral_edge = lateral.boundary.edge(seam);
    const int pieces = std::max(kMinCentreSamples,
                                static_cast<int>(std::ceil(lateral.edge_length_mm(seam) / kCentreSampleSpacing_mm)));
    for (int k = 0; k <= pieces; ++k) {
      const double share = static_cast<double>(k) / pieces;
      from.push_back(medial.to_forme(uv_at_share(*medial.segment, medial.boundary.edge(seam), share)));
      to.push_back(uv_at_share(*lateral.segment, lateral_edge, share));
    }
  }
  // Kabsch in 2D: about the centroids, the rotation angle is atan2(sum of cross products, sum of dot products).
  Point2 from_centre = Point2::Zero(), to_centre = Point2::Zero();
  for (std::size_t i = 0; i < from.size(); ++i) from_centre += from[i], to_centre += to[i];
  from_centre /= static_cast<double>(from.size());
  to_centre /= static_cast<double>(to.size());
  double cross = 0, dot = 0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    const Point2 a = from[i] - from_centre, b = to[i] - to_centre;
    cross += a.x() * b.y() - a.y() * b.x();
    dot += a.dot(b);
  }
  const double angle = std::atan2(cross, dot);
  medial.rotation << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  medial.translation = to_centre - medial.rotation * from_centre;
  layout.rotation_deg = angle * 180 / std::numbers::pi;

  for (FormeHalfLayout& laid : layout.halves) {
    laid.forme_uv_mm.resize(laid.segment->UV.rows(), 2);
    for (Eigen::Index v = 0; v < laid.segment->UV.rows(); ++v)
      laid.forme_uv_mm.row(v) = laid.to_forme(laid.segment->UV.row(v).transpose()).transpose();
  }
  double squares = 0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    const double gap_mm = (medial.rotation * from[i] + medial.translation - to[i]).norm();
    squares += gap_mm * gap_mm;
    layout.centre_worst_mm = std::max(layout.centre_worst_mm, gap_mm);
  }
  layout.centre_samples = static_cast<int>(from.size());
  layout.centre_rms_mm = std::sqrt(squares / static_cast<double>(from.size()));
  return layout;
}

}  // namespace lastcut
