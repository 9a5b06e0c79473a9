#pragma once
// A derby drawn on a generated reference last in the generator's frame, for the style tests and the
// style benchmark: a vamp line across the instep, a counter line round the heel, the lacing opening
// above the vamp line and the quarters' back seam above the counter cut along the centre seams, and a
// label in each of the four pieces (vamp, counter, medial and lateral quarter; a right last, medial +Y).
// Allowances by shoemaking's defaults: lasting 18 mm, folding 5 mm on the top edge, the vamp under the
// quarters and the quarters under the counter (underlay 8 mm), the other side of a line and the cut
// seams butted (0).
#include <Eigen/Core>

#include <cmath>
#include <string>
#include <vector>

#include "engine/style/piece_mold.hpp"
#include "engine/style/style_transfer.hpp"
#include "engine/style/upper_regions.hpp"
#include "tests/support/style_line_geometry.hpp"

namespace lastcut::test {

struct TransferredDerby {
  std::vector<TransferredCurve> lines;  // vamp line, counter line
  std::vector<SeamCut> cuts;
  std::vector<PieceLabel> labels;
};

// The mesh vertex that maximises `score` among those `near` accepts.
template <typename Near, typename Score>
Eigen::Vector3d vertex_where(const TriMesh& mesh, Near near, Score score) {
  Eigen::Vector3d best = Eigen::Vector3d::Constant(NAN);
  double best_score = -INFINITY;
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
    const Eigen::Vector3d p = mesh.V.row(v).transpose();
    if (near(p) && score(p) > best_score) best_score = score(p), best = p;
  }
  return best;
}

inline double seam_share(const TransferredCurve& curve, EdgeKind seam) {
  for (const TransferredPoint& point : curve.points)
    if (point.on_outline && point.edge == seam) return point.share;
  return NAN;
}

// reference_mesh: the reference last as scanned, generator frame (EU 42 proportions); transfer: from it
// to the new last.
inline TransferredDerby transfer_derby(const TriMesh& reference_mesh, const StyleTransfer& transfer) {
  TransferredDerby derby;
  derby.lines = {transfer.transfer_curve(plane_section_through(reference_mesh, {1, 0, 0.35}, {170, 0, 40})),
                 transfer.transfer_curve(plane_section_through(reference_mesh, {0.45, 0, 1}, {0, 0, 60}))};
  derby.cuts = {{EdgeKind::FrontSeam, seam_share(derby.lines[0], EdgeKind::FrontSeam), 1.0},
                {EdgeKind::BackSeam, seam_share(derby.lines[1], EdgeKind::BackSeam), 1.0}};
  const auto label = [&](const std::string& name, const Eigen::Vector3d& at) {
    return PieceLabel{name, transfer.transfer_point(at).value_or(TransferredPoint{})};
  };
  const TriMesh& m = reference_mesh;
  const auto side_at_110 = [](const Eigen::Vector3d& p) { return std::abs(p.x() - 110) < 2 && std::abs(p.z() - 50) < 3; };
  derby.labels = {
      label("vamp", vertex_where(m, [](const Eigen::Vector3d& p) { return std::abs(p.x() - 240) < 2 && std::abs(p.y()) < 5; },
                                 [](const Eigen::Vector3d& p) { return p.z(); })),
      label("counter", vertex_where(m, [](const Eigen::Vector3d& p) { return std::abs(p.z() - 40) < 2 && std::abs(p.y()) < 5; },
                                    [](const Eigen::Vector3d& p) { return -p.x(); })),
      label("medial quarter", vertex_where(m, side_at_110, [](const Eigen::Vector3d& p) { return p.y(); })),
      label("lateral quarter", vertex_where(m, side_at_110, [](const Eigen::Vector3d& p) { return -p.y(); }))};
  return derby;
}

inline double derby_allowance(const std::string& piece, const PieceEdgeSource& source) {
  switch (source.kind) {
    case PieceEdgeSource::Kind::Feather: return 18;
    case PieceEdgeSource::Kind::Top: return 5;
    case PieceEdgeSource::Kind::FrontSeam:
    case PieceEdgeSource::Kind::BackSeam: return 0;
    case PieceEdgeSource::Kind::Line:
      if (source.line == 0) return piece == "vamp" ? 8 : 0;       // the vamp line
      return piece.find("quarter") != std::string::npos ? 8 : 0;  // the counter line
  }
  return 0;
}

}  // namespace lastcut::test
