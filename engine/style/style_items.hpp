#pragma once
// A style's pieces for one scanned last as nest items, the one way every front door (the daemon's
// style jobs, the yield benchmark) turns them into what is cut: each piece as a pattern piece
// (piece_pattern.hpp, the same piece a DXF-AAMA file carries) then items_from_pattern, with the
// leather rules the style gives the piece or, where it gives none, its material's default.
#include <functional>
#include <string>
#include <vector>

#include "engine/nest/pattern_items.hpp"
#include "engine/style/style_pieces.hpp"

namespace lastcut {

struct StyleNestSpec {
  std::string style;           // the style's name, on the labels
  std::string size;            // e.g. "42"
  std::string foot;            // "left" or "right": the scanned last's foot
  int shoes = 1;               // how many shoes of this foot (a piece's demand is its quantity x shoes)
  bool other_foot = false;     // also the other foot's pieces, mirrored (a pair from one scan)
  std::vector<double> rotations_deg;  // empty = free rotation
  bool draw_sew_lines = false;        // PatternNestSpec::draw_sew_lines: the seams' lines drawn too
  // The rules of a material where the style gives a piece none (grain free, any grade when empty).
  std::function<PieceRules(const std::string& material)> material_rules;
  // The text on a piece; `twin` is the mirrored copy. Empty: "STYLE SIZE PIECE FOOT".
  std::function<std::string(const PatternPiece& piece, bool twin)> label;
};

// The items of `pieces` (the pieces of one last, make_style_pieces), numbered 0.. as
// items_from_pattern numbers them. Throws EngineError as items_from_pattern.
std::vector<NestItem> items_from_style(const StyleResult& pieces, const StyleNestSpec& spec);

// The rules of one piece: the style's own where it gives them, else its material's.
PieceRules style_piece_rules(const StylePiece& piece, const std::function<PieceRules(const std::string&)>& material_rules);

}  // namespace lastcut
