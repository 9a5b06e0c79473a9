#pragma once
// A style's pieces on a scanned last, start to end (issue 34, points 2 and 3): the style's lines and
// labels are transferred from the reference last (style_transfer.hpp), the new last's upper is split
// into the pieces (upper_regions.hpp), each piece's surface is cut out (piece_surface.hpp), moved off
// the last by half its thickness (piece_thickness.hpp), flattened and grown by its allowances
// (piece_mold.hpp), and given its notches (piece_notches.hpp) and grain line (piece_grain.hpp); the
// seams' lengths on both sides are reported (seam_report.hpp).
#include <string>
#include <vector>

#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/piece_grain.hpp"
#include "engine/style/piece_mold.hpp"
#include "engine/style/piece_notches.hpp"
#include "engine/style/seam_report.hpp"
#include "engine/style/style_definition.hpp"

namespace lastcut {

struct StylePieceResult {
  StylePiece spec;
  PieceSurface surface;  // 3D, the new last's canonical frame, on the last (not moved by the thickness)
  double thickness_mm = 0;  // its material's: flattened from its mid-surface, half of it off the last
  PieceMold mold;        // its marks are the notches below, as cut
  std::vector<PieceNotch> notches;
  GrainLine grain;
};

struct StyleResult {
  std::vector<StylePieceResult> pieces;  // in the style's order
  double upper_area_mm2 = 0;             // the new last's two halves
  double pieces_area_mm2 = 0;            // the outer pieces' 3D surfaces, together (each layer covers the upper again)
  std::vector<SeamReport> seams;         // every sewn curve: its length on the pieces of both sides ("vamp (lining)": a layer's)
  std::vector<std::string> notes;        // one line each: points of lines off the upper, ...
};

// reference, target: scan_to_molds of the reference last and of the new one, both segmented with
// named halves; mold_options.surface_offset_mm is set per piece from its thickness. Throws EngineError
// (one line) when the style does not fit: a line rule or seam cut naming no line, a seam cut's line
// that does not cross its seam, a label off the upper, a region without a label or with two, a piece
// that is not one patch or whose mid-surface folds.
StyleResult make_style_pieces(const StyleDefinition& style, const ScanResult& reference, const ScanResult& target,
                              const PieceMoldOptions& mold_options = {});

// Whether `line` parts the pieces of `layer` ("": the outer pieces): a layer's own lines; the outer
// pieces are parted by every line but those of a partial layer (a tongue's outline parts only the tongue).
bool line_parts_layer(const StyleDefinition& style, const std::string& layer, const std::string& line);

// The allowance of an edge of a piece by the style's rules (see style_definition.hpp), the piece's own
// allowances where it has them.
double style_allowance(const StyleDefinition& style, const StylePiece& piece, const PieceEdgeSource& source);

}  // namespace lastcut
