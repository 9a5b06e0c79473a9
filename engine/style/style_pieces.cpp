#include "engine/style/style_pieces.hpp"

#include <algorithm>
#include <optional>

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

// The pieces of one layer of the style ("": the outer pieces), and their seams.
struct StyleLayerResult {
  std::vector<StylePieceResult> pieces;
  std::vector<std::size_t> style_index;  // each piece's place in style.pieces
  std::vector<SeamReport> seams;
};

// The [[layer]] of that name; nullptr when the style has none.
const StyleLayer* find_layer(const StyleDefinition& style, const std::string& layer) {
  const auto found = std::find_if(style.layers.begin(), style.layers.end(), [&](const StyleLayer& l) { return l.name == layer; });
  return found == style.layers.end() ? nullptr : &*found;
}

// The layer's lines: the transferred lines it is parted along (line_parts_layer), the others left empty
// so that every line keeps its index (PieceEdgeSource::line) and its name in the seams and notches.
std::vector<TransferredCurve> lines_of_layer(const StyleDefinition& style, const std::string& layer,
                                             const std::vector<TransferredCurve>& lines) {
  if (const StyleLayer* found = layer.empty() ? nullptr : find_layer(style, layer))
    for (const std::string& name : found->lines) line_index(style, name, "the layer " + layer);
  std::vector<TransferredCurve> kept(lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (line_parts_layer(style, layer, style.lines[i].name)) kept[i] = lines[i];
  return kept;
}

StyleLayerResult layer_pieces(const StyleDefinition& style, const std::string& layer, const StyleTransfer& transfer,
                              const std::vector<TransferredCurve>& all_lines,
                              const std::vector<std::pair<std::string, SeamCut>>& all_cuts,
                              const std::array<const SegmentResult*, 2>& halves, const Eigen::Affine3d& scan_to_canonical,
                              const PieceMoldOptions& mold_options) {
  StyleLayerResult result;
  const std::vector<TransferredCurve> lines = lines_of_layer(style, layer, all_lines);
  std::vector<SeamCut> cuts;
  for (const auto& [cut_layer, cut] : all_cuts)
    if (cut_layer == layer) cuts.push_back(cut);
  std::vector<PieceLabel> labels;
  for (std::size_t p = 0; p < style.pieces.size(); ++p) {
    const StylePiece& piece = style.pieces[p];
    if (piece.layer != layer) continue;
    const std::optional<TransferredPoint> at = transfer.transfer_point(piece.label_mm);
    if (!at) throw EngineError("the label of piece " + piece.name + " is not on the reference last's upper");
    labels.push_back({piece.name, *at});
    result.style_index.push_back(p);
  }
  if (labels.empty()) return result;  // a style of linings only, or a layer without pieces
  const StyleLayer* layer_spec = layer.empty() ? nullptr : find_layer(style, layer);
  const bool partial = layer_spec && layer_spec->partial;
  const std::vector<PieceRegion> regions = piece_regions(halves, lines, labels, cuts, partial);
  const PieceEdgeCurves curves = piece_edge_curves(halves, lines, scan_to_canonical);
  for (std::size_t k = 0; k < regions.size(); ++k) {
    StylePieceResult piece;
    piece.spec = style.pieces[result.style_index[k]];
    piece.thickness_mm = piece.spec.thickness_mm.value_or(style.thickness_mm);
    PieceMoldOptions options = mold_options;
    options.surface_offset_mm = mid_surface_offset_mm(piece.thickness_mm);
    // A partial layer's lines are sewn to nothing: no length to hold them to (holding a tongue's outline
    // at its length on the curved instep stretched it 2 % in area).
    if (partial) options.hold_sewn_lengths = false;
    try {
      piece.surface = cut_piece_surface(halves, regions[k], cuts);
      piece.mold = make_piece_mold(
          piece.surface, curves, [&](const PieceEdgeSource& source) { return style_allowance(style, piece.spec, source); },
          options);
    } catch (const EngineError& error) {
      const std::string reason = error.what();
      if (reason.find("piece " + piece.spec.name) != std::string::npos) throw;
      throw EngineError("piece " + piece.spec.name + ": " + reason);
    }
    result.pieces.push_back(std::move(piece));
  }
  // Notches, grain lines and the seams' lengths on both sides, within the layer. A partial layer's lines
  // are its pieces' own edges, sewn to nothing there.
  std::vector<std::string> line_names;
  for (const StyleLine& line : style.lines) line_names.push_back(line.name);
  const std::vector<SewnCurve> sewn = partial ? std::vector<SewnCurve>{} : sewn_curves(curves, line_names);
  const std::vector<NotchPoint> notch_points =
      seam_notch_points(sewn, line_junctions(lines, line_names, scan_to_canonical), style.balance_notch_spacing_mm);
  std::vector<std::pair<const PieceSurface*, const PieceMold*>> molds;
  for (StylePieceResult& piece : result.pieces) {
    piece.notches = place_piece_notches(piece.surface, notch_points, piece.mold);
    piece.grain = piece_grain_line(piece.surface, piece.mold, piece.spec.grain_deg);
    molds.emplace_back(&piece.surface, &piece.mold);
  }
  result.seams = seam_reports(sewn, molds);
  if (!layer.empty())  // "vamp (lining)": the same line sews the outer pieces and this layer's
    for (SeamReport& seam : result.seams) seam.seam += " (" + layer + ")";
  return result;
}

}  // namespace

bool line_parts_layer(const StyleDefinition& style, const std::string& layer, const std::string& line) {
  if (layer.empty()) {
    return std::none_of(style.layers.begin(), style.layers.end(), [&](const StyleLayer& l) {
      return l.partial && std::find(l.lines.begin(), l.lines.end(), line) != l.lines.end();
    });
  }
  const StyleLayer* found = find_layer(style, layer);
  return found && std::find(found->lines.begin(), found->lines.end(), line) != found->lines.end();
}

double style_allowance(const StyleDefinition& style, const StylePiece& piece, const PieceEdgeSource& source) {
  const StyleAllowances& a = piece.allowances ? *piece.allowances : style.allowances;
  switch (source.kind) {
    case PieceEdgeSource::Kind::Feather: return a.lasting_mm;
    case PieceEdgeSource::Kind::Top: return a.folding_mm;
    case PieceEdgeSource::Kind::FrontSeam:
    case PieceEdgeSource::Kind::BackSeam: return a.butted_mm;
    case PieceEdgeSource::Kind::Line: {
      const std::string& line = style.lines.at(static_cast<std::size_t>(source.line)).name;
      for (const StyleLineRule& rule : style.line_rules)
        if (rule.line == line && rule.under == piece.name) return a.underlay_mm;
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
  std::vector<std::pair<std::string, SeamCut>> cuts;  // (layer, cut)
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
    cuts.push_back({cut.layer, {cut.seam, from_share, 1.0}});
  }
  const std::array<const SegmentResult*, 2> halves = {&named_half(target, "medial"), &named_half(target, "lateral")};
  for (const SegmentResult* half : halves) result.upper_area_mm2 += half->measures.area_3d_mm2;
  std::vector<std::optional<StylePieceResult>> made(style.pieces.size());  // in the style's order
  std::vector<std::string> layer_names = {""};
  for (const StyleLayer& layer : style.layers) layer_names.push_back(layer.name);
  for (const std::string& layer : layer_names) {
    StyleLayerResult pieces = layer_pieces(style, layer, transfer, lines, cuts, halves, target.scan_to_canonical, mold_options);
    for (std::size_t k = 0; k < pieces.pieces.size(); ++k) {
      if (layer.empty()) result.pieces_area_mm2 += pieces.pieces[k].surface.area_mm2;
      made[pieces.style_index[k]] = std::move(pieces.pieces[k]);
    }
    result.seams.insert(result.seams.end(), pieces.seams.begin(), pieces.seams.end());
  }
  for (std::size_t p = 0; p < made.size(); ++p) {
    if (!made[p]) throw EngineError("piece " + style.pieces[p].name + " names the layer " + style.pieces[p].layer + ", which the style does not have");
    result.pieces.push_back(std::move(*made[p]));
  }
  return result;
}

}  // namespace lastcut
