#include "engine/style/style_transfer.hpp"

#include <cmath>
#include <tuple>

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

  // A place on the target half: its 3D point (canonical frame) and its point in the half's flattening.
  struct Spot {
    Eigen::Vector3d point;
    Eigen::Vector2d uv;
  };

  Spot target_spot(int a, int b, double weight_b) const {
    return {(1 - weight_b) * target.mesh3d.V.row(a).transpose() + weight_b * target.mesh3d.V.row(b).transpose(),
            (1 - weight_b) * target.UV.row(a).transpose() + weight_b * target.UV.row(b).transpose()};
  }

  // Where on the reference's outline the hit lies (one vertex, or two on an outline edge): the edge and
  // the share of its 3D length. Nothing for a hit inside the half.
  std::optional<std::pair<EdgeKind, double>> outline_share(const SurfaceHit& hit) const {
    std::vector<std::pair<int, double>> corners;
    for (int k = 0; k < 3; ++k)
      if (hit.barycentric(k) > 0) corners.emplace_back(reference.mesh3d.F(hit.face, k), hit.barycentric(k));
    if (corners.size() == 2) {
      const auto span = map.reference_outline.spans.find(FormeBoundary::edge_key(corners[0].first, corners[1].first));
      if (span == map.reference_outline.spans.end()) return std::nullopt;
      const auto& s = span->second;
      const double weight_v = corners[0].first == s.v ? corners[0].second : corners[1].second;
      return std::pair{s.kind, (1 - weight_v) * s.share_u + weight_v * s.share_v};
    }
    if (corners.size() == 1)
      for (const FormeEdge& edge : map.reference_outline.edges)
        for (std::size_t i = 0; i < edge.vertices.size(); ++i)
          if (edge.vertices[i] == corners[0].first) return std::pair{edge.kind, edge.share[i]};
    return std::nullopt;
  }

  // The target's outline point at the same share of the same edge.
  Spot along_outline(EdgeKind kind, double share) const {
    const EdgeSpot spot = spot_at_share(map.target_outline.edge(kind), share);
    return target_spot(spot.a, spot.b, spot.weight_b);
  }

  Spot carry(const SurfaceHit& hit) const {
    Eigen::Vector2d uv = Eigen::Vector2d::Zero();
    for (int k = 0; k < 3; ++k) uv += hit.barycentric(k) * map.target_uv.row(reference.mesh3d.F(hit.face, k)).transpose();
    const SurfaceHit onto = target_forme.closest(uv);
    Spot spot{Eigen::Vector3d::Zero(), Eigen::Vector2d::Zero()};
    for (int k = 0; k < 3; ++k) {
      const int v = target.mesh3d.F(onto.face, k);
      spot.point += onto.barycentric(k) * target.mesh3d.V.row(v).transpose();
      spot.uv += onto.barycentric(k) * target.UV.row(v).transpose();
    }
    return spot;
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

StyleTransfer::Located StyleTransfer::locate(const Eigen::Vector3d& reference_point) const {
  const Eigen::Vector3d canonical = reference_to_canonical_ * reference_point;
  Located located;
  located.hit.distance_mm = INFINITY;
  for (const auto& half : halves_) {
    const SurfaceHit candidate = half->reference_surface.closest(canonical);
    if (candidate.distance_mm < located.hit.distance_mm) {
      located.hit = candidate;
      located.half = half.get();
    }
  }
  located.outline = located.half->outline_share(located.hit);
  // Beyond an edge the closest point is on the outline and the offset runs along the surface, not off it.
  located.on_upper = located.hit.distance_mm <= (located.outline ? kOnEdge_mm : options_.max_off_surface_mm);
  return located;
}

TransferredPoint StyleTransfer::carry(const Located& located) const {
  return carry(located, *located.half);
}

TransferredPoint StyleTransfer::carry(const Located& located, const HalfPair& half) const {
  TransferredPoint result;
  result.half = half.reference.name;
  result.on_outline = located.outline.has_value();
  if (located.outline) std::tie(result.edge, result.share) = *located.outline;
  const HalfPair::Spot spot =
      located.outline ? half.along_outline(located.outline->first, located.outline->second) : half.carry(located.hit);
  result.position_mm = target_canonical_to_scan_ * spot.point;
  result.forme_uv_mm = spot.uv;
  return result;
}

std::pair<TransferredPoint, TransferredPoint> StyleTransfer::seam_crossing(Eigen::Vector3d from, Eigen::Vector3d to) const {
  const HalfPair* from_half = locate(from).half;
  for (int halving = 0; halving < kCrossingHalvings; ++halving) {
    const Eigen::Vector3d middle = 0.5 * (from + to);
    (locate(middle).half == from_half ? from : to) = middle;
  }
  // The seam is an outline edge of both halves with the same shares: the crossing's share on the first
  // half's seam places it on the second's too. The bisection ends a hair inside the first half, so the
  // hit's weight on the far vertex is snapped to the seam.
  Located crossing = locate(from);
  for (int k = 0; k < 3; ++k)
    if (crossing.hit.barycentric(k) < kSeamSnapWeight) crossing.hit.barycentric(k) = 0;
  crossing.hit.barycentric /= crossing.hit.barycentric.sum();
  crossing.outline = from_half->outline_share(crossing.hit);
  const HalfPair* other = halves_[0].get() == from_half ? halves_[1].get() : halves_[0].get();
  if (!crossing.outline || (crossing.outline->first != EdgeKind::FrontSeam && crossing.outline->first != EdgeKind::BackSeam)) {
    // The halves meet only at the seams; should a crossing not lie on one, each side is carried as found.
    return {carry(locate(from)), carry(locate(to))};
  }
  return {carry(crossing, *from_half), carry(crossing, *other)};
}

std::optional<TransferredPoint> StyleTransfer::transfer_point(const Eigen::Vector3d& reference_point) const {
  const Located located = locate(reference_point);
  if (!located.on_upper) return std::nullopt;
  return carry(located);
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
  // Where the line leaves or enters the upper between two samples, the crossing is found by bisection and
  // carried as an outline point, so the line ends exactly on the new last's edge.
  std::optional<std::pair<Eigen::Vector3d, Located>> previous;
  for (const Eigen::Vector3d& sample : samples) {
    const Located located = locate(sample);
    if (previous && previous->second.on_upper != located.on_upper) {
      Eigen::Vector3d inside = located.on_upper ? sample : previous->first;
      Eigen::Vector3d outside = located.on_upper ? previous->first : sample;
      for (int halving = 0; halving < kCrossingHalvings; ++halving) {
        const Eigen::Vector3d middle = 0.5 * (inside + outside);
        (locate(middle).on_upper ? inside : outside) = middle;
      }
      Located crossing = locate(inside);
      if (!crossing.outline) crossing = locate(outside);  // the outside end's hit lies on the outline
      if (crossing.outline) curve.points.push_back(carry(crossing));
    }
    if (previous && previous->second.on_upper && located.on_upper && previous->second.half != located.half) {
      const auto [leaving, entering] = seam_crossing(previous->first, sample);
      curve.points.push_back(leaving);
      curve.points.push_back(entering);
    }
    if (located.on_upper)
      curve.points.push_back(carry(located));
    else
      ++curve.dropped_points;
    previous.emplace(sample, located);
  }
  curve.closed = polyline.size() > 2 && (polyline.back() - polyline.front()).norm() < kSamePoint_mm;
  return curve;
}

std::vector<std::vector<Eigen::Vector3d>> runs_on_upper(const TransferredCurve& curve) {
  if (curve.points.empty()) return {};  // a line that does not part this layer's pieces (style_pieces.cpp)
  std::vector<std::vector<Eigen::Vector3d>> runs(1);
  for (std::size_t i = 0; i < curve.points.size(); ++i) {
    const Eigen::Vector3d& p = curve.points[i].position_mm;
    if (i > 0) {
      const double step_mm = (p - curve.points[i - 1].position_mm).norm();
      if (step_mm < kSamePoint_mm) continue;  // a seam crossing comes once per half, at one point
      if (step_mm > kRunGap_mm && on_upper_edge(curve.points[i - 1]) && on_upper_edge(curve.points[i])) runs.emplace_back();
    }
    runs.back().push_back(p);
  }
  if (curve.closed && runs.size() > 1 && !on_upper_edge(curve.points.front()) &&
      (runs.back().back() - runs.front().front()).norm() < kSamePoint_mm) {
    runs.back().insert(runs.back().end(), runs.front().begin() + 1, runs.front().end());
    runs.erase(runs.begin());
  }
  std::erase_if(runs, [](const auto& run) { return run.size() < 2; });
  return runs;
}

int StyleTransfer::folded_triangles() const {
  int folded = 0;
  for (const auto& half : halves_) folded += half->map.folded_triangles;
  return folded;
}

}  // namespace lastcut
