#pragma once
// Nest items from pattern pieces: a DXF-AAMA pattern set a pattern room sends (engine/pattern), or
// a style's pieces made for one scanned last (engine/style/piece_pattern.hpp). One item per piece
// (and per mirrored twin for the other foot), its cut line as the shape, its notches as marks named
// "notch", its internal lines (DXF-AAMA layer 8: the net line, style lines) as drawn lines the pen
// draws and nothing cuts, its sew lines (layer 14) too when asked, its grain line as the item's
// grain, its leather rules (grain tolerance, lowest grade) from `rules`.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "engine/nest/nest_problem.hpp"
#include "engine/pattern/pattern_piece.hpp"

namespace lastcut {

// What the cutting room asks of one piece's leather (docs/hides.md, Grades).
struct PieceRules {
  std::optional<double> grain_tolerance_deg;  // grain line along the hide's backbone within this; nullopt: free
  int min_quality = 0;                        // lowest leather grade the piece may lie on
};

struct PatternNestSpec {
  int sets = 1;                 // copies of the whole set: each piece's demand is its quantity x sets
  bool mirrored_twins = false;  // add each piece mirrored (x -> -x) for the other foot
  std::vector<double> rotations_deg;  // empty = free rotation
  double notch_depth_mm = 3;    // a notch is cut this far into the piece along its inward direction
  // Also draw the sew lines (layer 14) on the piece; off by default, as the stitching room works
  // from the edge and the net line, and every extra pen line costs table time.
  bool draw_sew_lines = false;
  // The rules of a piece; empty: grain free, any grade.
  std::function<PieceRules(const PatternPiece& piece)> rules;
  // The text on the piece; `twin` is the mirrored copy. Empty: "NAME SIZE", " (other foot)" for a twin.
  std::function<std::string(const PatternPiece& piece, bool twin)> label;
};

// Items numbered 0.. in piece order (each piece, then its twin). A piece without a grain line has
// its grain free whatever its rules say. Throws EngineError naming the piece when there are no
// pieces, no sets, a quantity below 1, a cut line without area, an internal line (or, when drawn,
// a sew line) of fewer than 2 points, a grain tolerance outside 0..90 deg, or a notch depth that is
// not positive.
std::vector<NestItem> items_from_pattern(const std::vector<PatternPiece>& pieces, const PatternNestSpec& spec);

}  // namespace lastcut
