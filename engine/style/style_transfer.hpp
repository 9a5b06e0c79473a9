#pragma once
// Style lines taken from a reference last to another scanned last (issue 34, point 2): a point of the
// reference's upper is found on its medial or lateral half, carried through that half's forme map
// (forme_map.hpp) into the new last's flattening of the same half, and lifted back onto the new last's
// surface. A point on the feather line or the top edge (or a centre seam) goes by its share of that edge,
// so it lands exactly on the new last's edge. Curves are resampled on the reference first, so the
// transferred curve follows the new surface and stays as smooth as drawn; where a curve leaves the upper
// (runs over the feather line onto the sole, or over the top edge), the crossing is found and kept, and the
// samples beyond it are dropped.
//
// precompute (the constructor) / solve (transfer_*) split: the maps and point locators are built once
// per pair of lasts, every line of a style then costs a few tree searches per millimetre.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/mold/edge_allowance.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/triangle_locator.hpp"

namespace lastcut {

struct StyleTransferOptions {
  double max_off_surface_mm = 1.5;  // a reference point farther than this from the upper is not on it (as drawn
                                    // on a coarser copy of the last); beyond an edge the limit is kOnEdge_mm
  double sample_spacing_mm = 1.0;   // curves are resampled this finely on the reference before transfer
};

struct TransferredPoint {
  Eigen::Vector3d position_mm = Eigen::Vector3d::Zero();  // on the new last, in its scan's frame
  std::string half;           // "medial" or "lateral"
  Eigen::Vector2d forme_uv_mm = Eigen::Vector2d::Zero();  // in that half's flattening (SegmentResult::UV)
  bool on_outline = false;    // on the feather line, the top edge or a centre seam
  EdgeKind edge = EdgeKind::Feather;  // which, when on_outline
  double share = 0;                   // and where along it (forme_boundary.hpp), the same on both lasts
};

struct TransferredCurve {
  // In the order of the reference curve. Where it crosses a centre seam, the crossing comes twice, as a
  // point of the half it leaves and of the half it enters (same 3D point, each half's flattening).
  std::vector<TransferredPoint> points;
  int dropped_points = 0;                // resampled points that were not on the reference's upper
  bool closed = false;                   // the reference polyline ends where it starts
};

// A transferred curve as the runs it makes on the new last's upper, each >= 2 points (positions, the new
// scan's frame). Where the curve leaves the upper and comes back (over the sole, across the top opening)
// its two crossings follow each other farther apart than kRunGap_mm: they end one run and start the next,
// and no chord is drawn across the sole. A closed curve whose start lies on the upper has its last run go
// on into its first.
inline constexpr double kSamePoint_mm = 1e-6;  // closer than this, two transferred points are one
inline constexpr double kRunGap_mm = 3.0;  // 3 reference samples; a line through a corner of the upper enters and leaves within one
std::vector<std::vector<Eigen::Vector3d>> runs_on_upper(const TransferredCurve& curve);

// On the feather line or the top edge: where a line ends or leaves the upper (a centre seam is inside it).
inline bool on_upper_edge(const TransferredPoint& point) {
  return point.on_outline && (point.edge == EdgeKind::Feather || point.edge == EdgeKind::Top);
}

class StyleTransfer {
 public:
  // reference, target: segmented scans (scan_to_molds) with named medial and lateral halves; kept by
  // reference, they must outlive the transfer. Throws EngineError (one line) when a last has no
  // medial and lateral half or a half's outline cannot be split at its landmarks.
  StyleTransfer(const ScanResult& reference, const ScanResult& target, const StyleTransferOptions& options = {});
  ~StyleTransfer();
  StyleTransfer(StyleTransfer&&) noexcept;

  // reference_point: in the reference scan's frame (mm). Nothing when it is not on the reference's upper.
  std::optional<TransferredPoint> transfer_point(const Eigen::Vector3d& reference_point) const;
  // polyline: in the reference scan's frame (mm), >= 1 point.
  TransferredCurve transfer_curve(const std::vector<Eigen::Vector3d>& polyline) const;

  // A point whose closest point on the reference's upper lies on its outline is beyond the edge unless this
  // close (mm): the line has left the upper there.
  static constexpr double kOnEdge_mm = 1e-3;

  // Reference triangles whose image in the target forme is folded, summed over both halves (0 for a good map).
  int folded_triangles() const;

 private:
  struct HalfPair;
  struct Located {
    const HalfPair* half = nullptr;
    SurfaceHit hit;
    std::optional<std::pair<EdgeKind, double>> outline;  // the hit's edge and share, when on the outline
    bool on_upper = false;
  };
  static constexpr int kCrossingHalvings = 30;  // a 1 mm sample step found to 1e-9 mm
  static constexpr double kSeamSnapWeight = 1e-6;  // a barycentric weight this small at a seam crossing is 0

  Located locate(const Eigen::Vector3d& reference_point) const;  // reference scan frame
  TransferredPoint carry(const Located& located) const;
  TransferredPoint carry(const Located& located, const HalfPair& half) const;
  // The crossing of a centre seam between two samples on different halves (reference scan frame).
  std::pair<TransferredPoint, TransferredPoint> seam_crossing(Eigen::Vector3d from, Eigen::Vector3d to) const;

  std::vector<std::unique_ptr<HalfPair>> halves_;
  Eigen::Affine3d reference_to_canonical_, target_canonical_to_scan_;
  StyleTransferOptions options_;
};

}  // namespace lastcut
