#include "engine/style/style_transfer.hpp"

#include <cmath>

#include "engine/core/engine_error.hpp"
#include "engine/style/forme_map.hpp"
#include "engine/style/triangle_locator.hpp"

namespace lastcut {

struct StyleTransfer::HalfPair {
  const SegmentResult& reference;
  const SegmentResult& target;
  FormeMap map;
  SurfaceLocator reference_surface;
  FlatLocator target_forme;

  HalfPair(const SegmentResult& from, const SegmentResult& to)
      : reference(from),
        target(to),
        map(map_forme({from.mesh3d, from.topology, from.UV, from.landmarks}, {to.mesh3d, to.topology, to.UV, to.landmarks})),
        reference_surface(from.mesh3d.V, from.mesh3d.F),
        target_forme(to.UV, to.mesh3d.F) {}

  Eigen::Vector3d target_point(int a, int b, double weight_b) const {
    return (1 - weight_b) * target.mesh3d.V.row(a).transpose() + weight_b * target.mesh3d.V.row(b).transpose();
  }

  // The hit's point on the target when it lies on the reference's outline (one vertex, or two on an
  // outline edge): by its share of the same outline edge.
  std::optional<Eigen::Vector3d> along_outline(const SurfaceHit& hit) const {
    std::vector<std::pair<int, double>> corners;
    for (int k = 0; k < 3; ++k)
      if (hit.barycentric(k) > 0) corners.emplace_back(reference.mesh3d.F(hit.face, k), hit.barycentric(k));
    if (corners.size() == 2) {
      const auto span = map.reference_outline.spans.find(FormeBoundary::edge_key(corners[0].first, corners[1].first));
      if (span == map.reference_outline.spans.end()) return std::nullopt;
      const auto& s = span->second;
      const double weight_v = corners[0].first == s.v ? corners[0].second : corners[1].second;
      const EdgeSpot spot = spot_at_share(map.target_outline.edge(s.kind), (1 - weight_v) * s.share_u + weight_v * s.share_v);
      return target_point(spot.a, spot.b, spot.weight_b);
    }
    if (corners.size() == 1)
      for (const FormeEdge& edge : map.reference_outline.edges)
        for (std::size_t i = 0; i < edge.vertices.size(); ++i)
          if (edge.vertices[i] == corners[0].first) {
            const EdgeSpot spot = spot_at_share(map.target_outline.edge(edge.kind), edge.share[i]);
            return target_point(spot.a, spot.b, spot.weight_b);
          }
    return std::nullopt;
  }

  Eigen::Vector3d carry(const SurfaceHit& hit) const {
    Eigen::Vector2d uv = Eigen::Vector2d::Zero();
    for (int k = 0; k < 3; ++k) uv += hit.barycentric(k) * map.target_uv.row(reference.mesh3d.F(hit.face, k)).transpose();
    const SurfaceHit onto = target_forme.closest(uv);
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) point += onto.barycentric(k) * target.mesh3d.V.row(target.mesh3d.F(onto.face, k)).transpose();
    return point;
  }
};

namespace {

const SegmentResult& half_named(const ScanResult& scan, const std::string& name, const char* which) {
  for (const SegmentResult& segment : scan.segments)
    if (segment.name == name) return segment;
  throw EngineError(std::string("the ") + which + " last has no " + name +
                    " half (a style needs a last segmented with its side named)");
}

}  // namespace

StyleTransfer::StyleTransfer(const ScanResult& reference, const ScanResult& target, const StyleTransferOptions& options)
    : reference_to_canonical_(reference.scan_to_canonical),
      target_canonical_to_scan_(target.scan_to_canonical.inverse()),
      options_(options) {
  for (const char* name : {"medial", "lateral"})
    halves_.push_back(std::make_unique<HalfPair>(half_named(reference, name, "reference"), half_named(target, name, "new")));
}

StyleTransfer::~StyleTransfer() = default;
StyleTransfer::StyleTransfer(StyleTransfer&&) noexcept = default;

std::optional<TransferredPoint> StyleTransfer::transfer_point(const Eigen::Vector3d& reference_point) const {
  const Eigen::Vector3d canonical = reference_to_canonical_ * reference_point;
  const HalfPair* nearest = nullptr;
  SurfaceHit hit;
  hit.distance_mm = INFINITY;
  for (const auto& half : halves_) {
    const SurfaceHit candidate = half->reference_surface.closest(canonical);
    if (candidate.distance_mm < hit.distance_mm) {
      hit = candidate;
      nearest = half.get();
    }
  }
  if (!(hit.distance_mm <= options_.max_off_surface_mm)) return std::nullopt;
  TransferredPoint result;
  result.half = nearest->reference.name;
  const std::optional<Eigen::Vector3d> on_outline = nearest->along_outline(hit);
  result.on_outline = on_outline.has_value();
  result.position_mm = target_canonical_to_scan_ * (on_outline ? *on_outline : nearest->carry(hit));
  return result;
}

TransferredCurve StyleTransfer::transfer_curve(const std::vector<Eigen::Vector3d>& polyline) const {
  TransferredCurve curve;
  std::vector<Eigen::Vector3d> samples;
  for (std::size_t i = 0; i < polyline.size(); ++i) {
    if (i > 0) {
      const Eigen::Vector3d step = polyline[i] - polyline[i - 1];
      const int pieces = std::max(1, static_cast<int>(std::ceil(step.norm() / options_.sample_spacing_mm)));
      for (int k = 1; k < pieces; ++k) samples.push_back(polyline[i - 1] + step * (static_cast<double>(k) / pieces));
    }
    samples.push_back(polyline[i]);
  }
  for (const Eigen::Vector3d& sample : samples) {
    if (std::optional<TransferredPoint> point = transfer_point(sample))
      curve.points.push_back(std::move(*point));
    else
      ++curve.dropped_points;
  }
  return curve;
}

int StyleTransfer::folded_triangles() const {
  int folded = 0;
  for (const auto& half : halves_) folded += half->map.folded_triangles;
  return folded;
}

}  // namespace lastcut
