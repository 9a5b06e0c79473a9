// A style's pieces as nest items; see style_items.hpp.
#include "engine/style/style_items.hpp"

#include <map>

#include "engine/style/piece_pattern.hpp"

namespace lastcut {

PieceRules style_piece_rules(const StylePiece& piece, const std::function<PieceRules(const std::string&)>& material_rules) {
  PieceRules rules = material_rules ? material_rules(piece.material) : PieceRules{};
  if (piece.grain_tolerance_deg) rules.grain_tolerance_deg = *piece.grain_tolerance_deg;
  if (piece.min_quality) rules.min_quality = *piece.min_quality;
  return rules;
}

std::vector<NestItem> items_from_style(const StyleResult& pieces, const StyleNestSpec& spec) {
  std::vector<PatternPiece> patterns;
  std::map<std::string, PieceRules> rules_by_name;
  for (const StylePieceResult& piece : pieces.pieces) {
    patterns.push_back(pattern_piece(piece, spec.style, spec.size, spec.foot));
    rules_by_name[piece.spec.name] = style_piece_rules(piece.spec, spec.material_rules);
  }
  const std::string other_foot = spec.foot == "left" ? "right" : spec.foot == "right" ? "left" : "";
  PatternNestSpec pattern_spec;
  pattern_spec.sets = spec.shoes;
  pattern_spec.mirrored_twins = spec.other_foot;
  pattern_spec.rotations_deg = spec.rotations_deg;
  pattern_spec.draw_sew_lines = spec.draw_sew_lines;
  pattern_spec.rules = [&](const PatternPiece& piece) { return rules_by_name.at(piece.name); };
  pattern_spec.label = spec.label ? spec.label : [&](const PatternPiece& piece, bool twin) {
    std::string text = spec.style + " " + spec.size + " " + piece.name;
    const std::string& foot = twin ? other_foot : spec.foot;
    return foot.empty() ? text : text + " " + foot;
  };
  return items_from_pattern(patterns, pattern_spec);
}

}  // namespace lastcut
