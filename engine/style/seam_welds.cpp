// Where a piece is sewn across a centre seam; see seam_welds.hpp.
#include "engine/style/seam_welds.hpp"

#include <cmath>

#include "engine/style/forme_boundary.hpp"

namespace lastcut {

SeamWelds::SeamWelds(const std::array<const SegmentResult*, 2>& halves, const PieceRegion& piece,
                     const std::vector<SeamCut>& cuts)
    : joins_(piece.joins), cuts_(cuts) {
  if (joins_.empty()) return;  // nothing is welded across the halves
  for (const SegmentResult* half : halves) {
    const FormeBoundary boundary = forme_boundary(half->mesh3d, half->topology, half->landmarks);
    for (const EdgeKind kind : {EdgeKind::FrontSeam, EdgeKind::BackSeam}) {
      Seam seam{kind, {}, 0};
      for (const int v : boundary.edge(kind).vertices) seam.points.push_back(half->mesh3d.V.row(v).transpose());
      seam.length_mm = polyline_length_mm(seam.points);
      if (seam.length_mm > 0) seams_.push_back(std::move(seam));
    }
  }
}

bool SeamWelds::weldable(const Eigen::Vector3d& p) const {
  for (const Seam& seam : seams_) {
    const PolylineHit hit = closest_on_polyline(p, seam.points);
    if (hit.distance_mm > kOnSeam_mm) continue;
    bool cut = false;
    for (const SeamCut& c : cuts_)
      cut = cut || (c.seam == seam.kind && hit.arc_length_mm > c.from_share * seam.length_mm + kCutStart_mm &&
                    hit.arc_length_mm <= c.to_share * seam.length_mm + kOnSeam_mm);
    if (cut) continue;
    for (const PieceRegion::SeamJoin& join : joins_)
      if (join.seam == seam.kind && std::abs(hit.arc_length_mm - join.share * seam.length_mm) <= kJoinReach_mm) return true;
  }
  return false;
}

}  // namespace lastcut
