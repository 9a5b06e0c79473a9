#include "engine/style/style_pieces.hpp"

#include <algorithm>

#include "engine/core/engine_error.hpp"
#include "engine/style/piece_surface.hpp"
#include "engine/style/piece_thickness.hpp"
#include "engine/style/style_transfer.hpp"
#include "engine/style/upper_regions.hpp"

namespace lastcut {
namespace {

int line_index(const StyleDefinition& style, const std::string& name, const std::string& who) {
  for (std::size_t i = 0; i < style.lines.size(); ++i)
    if (style.lines[i].name == name) return static_cast<int>(i);
  throw EngineError(who + " names the line " + name + ", which the style's lines do not have");
}

const SegmentResult& named_half(const ScanResult& scan, const char* name) {
  for (const SegmentResult& segment : scan.segments)
    if (segment.name == name) return segment;
  throw EngineError(std::string("the last has no ") + name + " half (name its side)");
}

}  // namespace

double style_allowance(const StyleDefinition& style, const std::string& piece, const PieceEdgeSource& source) {
  const StyleAllowances& a = style.allowances;
  switch (source.kind) {
    case PieceEdgeSource::Kind::Feather: return a.lasting_mm;
    case PieceEdgeSource::Kind::Top: return a.folding_mm;
    case PieceEdgeSource::Kind::FrontSeam:
    case PieceEdgeSource::Kind::BackSeam: return a.butted_mm;
    case PieceEdgeSource::Kind::Line: {
      const std::string& line = style.lines.at(static_cast<std::size_t>(source.line)).name;
      for (const StyleLineRule& rule : style.line_rules)
        if (rule.line == line && rule.under == piece) return a.underlay_mm;
      return a.butted_mm;
    }
  }
  return a.butted_mm;
}

StyleResult make_style_pieces(const StyleDefinition& style, const ScanResult& reference, const ScanResult& target,
                              const PieceMoldOptions& mold_options) {
  StyleResult result;
  for (const StyleLineRule& rule : style.line_rules) {
    line_index(style, rule.line, "a line rule");
    if (!rule.under.empty() && std::none_of(style.pieces.begin(), style.pieces.end(),
                                            [&](const StylePiece& piece) { return piece.name == rule.under; }))
      throw EngineError("the rule of line " + rule.line + " puts piece " + rule.under + " under it, which the style does not have");
  }
  const StyleTransfer transfer(reference, target);
  std::vector<TransferredCurve> lines;
  for (const StyleLine& line : style.lines) {
    lines.push_back(transfer.transfer_curve(line.points_mm));
    if (lines.back().points.size() < 2) throw EngineError("the line " + line.name + " does not lie on the reference last's upper");
    if (lines.back().dropped_points > 0)
      result.notes.push_back("line " + line.name + ": " + std::to_string(lines.back().dropped_points) +
                             " points beyond the upper's edges left out");
  }
  std::vector<SeamCut> cuts;
  for (const StyleSeamCut& cut : style.seam_cuts) {
    if (cut.seam != EdgeKind::FrontSeam && cut.seam != EdgeKind::BackSeam)
      throw EngineError("a seam cut must be on the front or the back seam");
    double from_share = 0;
    if (!cut.from_line.empty()) {
      const TransferredCurve& line = lines[static_cast<std::size_t>(line_index(style, cut.from_line, "a seam cut"))];
      const auto crossing = std::find_if(line.points.begin(), line.points.end(), [&](const TransferredPoint& point) {
        return point.on_outline && point.edge == cut.seam;
      });
      if (crossing == line.points.end())
        throw EngineError(std::string("the ") + (cut.seam == EdgeKind::FrontSeam ? "front" : "back") + " seam's cut starts at line " +
                          cut.from_line + ", which does not cross it");
      from_share = crossing->share;
    }
    cuts.push_back({cut.seam, from_share, 1.0});
  }
  std::vector<PieceLabel> labels;
  for (const StylePiece& piece : style.pieces) {
    const std::optional<TransferredPoint> at = transfer.transfer_point(piece.label_mm);
    if (!at) throw EngineError("the label of piece " + piece.name + " is not on the reference last's upper");
    labels.push_back({piece.name, *at});
  }
  const std::array<const SegmentResult*, 2> halves = {&named_half(target, "medial"), &named_half(target, "lateral")};
  const std::vector<PieceRegion> regions = piece_regions(halves, lines, labels, cuts);
  const PieceEdgeCurves curves = piece_edge_curves(halves, lines, target.scan_to_canonical);
  for (const SegmentResult* half : halves) result.upper_area_mm2 += half->measures.area_3d_mm2;
  for (std::size_t p = 0; p < regions.size(); ++p) {
    StylePieceResult piece;
    piece.spec = style.pieces[p];
    piece.thickness_mm = piece.spec.thickness_mm.value_or(style.thickness_mm);
    PieceMoldOptions options = mold_options;
    options.surface_offset_mm = mid_surface_offset_mm(piece.thickness_mm);
    try {
      piece.surface = cut_piece_surface(halves, regions[p]);
      piece.mold = make_piece_mold(
          piece.surface, curves, [&](const PieceEdgeSource& source) { return style_allowance(style, piece.spec.name, source); },
          options);
    } catch (const EngineError& error) {
      const std::string reason = error.what();
      if (reason.find("piece " + piece.spec.name) != std::string::npos) throw;
      throw EngineError("piece " + piece.spec.name + ": " + reason);
    }
    result.pieces_area_mm2 += piece.surface.area_mm2;
    result.pieces.push_back(std::move(piece));
  }
  // Notches, grain lines and the seams' lengths on both sides.
  std::vector<std::string> line_names;
  for (const StyleLine& line : style.lines) line_names.push_back(line.name);
  const std::vector<SewnCurve> sewn = sewn_curves(curves, line_names);
  const std::vector<NotchPoint> notch_points =
      seam_notch_points(sewn, line_junctions(lines, line_names, target.scan_to_canonical), style.balance_notch_spacing_mm);
  std::vector<std::pair<const PieceSurface*, const PieceMold*>> molds;
  for (StylePieceResult& piece : result.pieces) {
    piece.notches = place_piece_notches(piece.surface, notch_points, piece.mold);
    piece.grain = piece_grain_line(piece.surface, piece.mold, piece.spec.grain_deg);
    molds.emplace_back(&piece.surface, &piece.mold);
  }
  result.seams = seam_reports(sewn, molds);
  return result;
}

}  // namespace lastcut
