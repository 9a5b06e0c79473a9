#pragma once
// A style's piece as a pattern piece the way pattern rooms exchange them (engine/pattern, DXF-AAMA):
// the cut line, the whole net line drawn on layer 8 (where the leather is lasted, folded or stitched),
// the sewn stretches of the net again on layer 14 (the stitch lines), the notches, the grain line and
// the piece's texts (style, size, foot, material, quantity per pair).
#include <string>

#include "engine/pattern/pattern_piece.hpp"
#include "engine/style/style_pieces.hpp"

namespace lastcut {

// size: the size label ("42"), foot: "left" or "right" (written as the Annotation). The
// quantity is per shoe: the file is one foot's (a pair is two files, or the same file cut mirrored).
PatternPiece pattern_piece(const StylePieceResult& piece, const std::string& style, const std::string& size, const std::string& foot);

}  // namespace lastcut
