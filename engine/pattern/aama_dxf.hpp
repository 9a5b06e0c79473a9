#pragma once
// Pattern pieces as DXF-AAMA files (AAMA's pattern exchange DXF, continued as ASTM D6673): what
// pattern CAD (Gerber, Lectra, Optitex, Valentina, Seamly2D) and cutting-room software exchange.
//
// The conventions this relies on, and where they come from (docs/aama-dxf.md has the detail):
//  - one BLOCK per piece, placed once with an INSERT in ENTITIES; the piece's "system text" is TEXT
//    on layer 1 inside its block: "Piece Name: ...", "Quantity: N", "Size: ...", "Style Name: ...",
//    "Category: ...", "Annotation: ..." (the AAMA layer convention as the Romans CAD support note
//    tabulates it, the ASTM D6673 summary in Patro's documentation, Valentina's DXF-AAMA export);
//  - numbered layers: 1 boundary (the cut line, one closed polyline), 4 notches, 7 grain line,
//    8 internal lines (drawn, not cut), 14 sew lines (same sources);
//  - a notch is a POINT on layer 4 at the cut line whose angle (group 50, degrees counter-clockwise
//    from +x) points into the piece: what Valentina's DXF-AAMA and DXF-ASTM exports write
//    (ExportAAMANotch: a POINT at the passmark's base line start, angle = that line's angle).
//    Older exports (Seamly2D, Valentina before it) drew the notch as a short LINE on layer 4 from
//    the cut line inward; the reader takes both;
//  - the grain line is one LINE on layer 7, from -> to is the arrow's direction (Valentina);
//  - the file is R12 ASCII (AC1009), the version every pattern system reads (ezdxf's ASTM-D6673
//    exporter writes R12 only, Valentina's export defaults to it); units are millimetres, said twice:
//    $INSUNITS 4 in the HEADER and the style system text "Units: METRIC" on layer 1 in ENTITIES.
//
// Written (aama_dxf_text): the pieces side by side on the x axis, 20 mm apart, bottoms at y = 0, each
// its own block named by the piece (characters R12 does not allow in a name become '_', a repeated
// name gets "_2", "_3"). The block holds the piece in its own coordinates; only the INSERT moves it.
// Texts are 7-bit ASCII (what the standard allows): a label with any other character is refused.
//
// Read (read_aama_dxf_text): every block an INSERT in ENTITIES names, once, in INSERT order, in the
// block's own coordinates (the INSERT's placement is the file's layout, not the piece). The cut line
// may be a POLYLINE or an LWPOLYLINE (bulges flattened within 0.05 mm) and is returned
// counter-clockwise; a missing Quantity reads as 1, a missing Style Name as the style system text's;
// a notch POINT without an angle points along the inward normal of the nearest cut-line edge; the
// longest LINE on layer 7 is the grain line (arrow heads beside it are ignored). Units: $INSUNITS
// (0 = none read as mm) and a "Units:" text (METRIC/MM, CM, ENGLISH/INCH) must agree when both are
// there. Refusals, each an EngineError of one line naming the file, e.g.
//   "<file> is not a DXF file: line 3 is not a group code"
//   "<file>: no piece blocks (DXF-AAMA places each piece as a BLOCK with an INSERT)"
//   "<file>: piece \"vamp\": its cut line on layer 1 is open"
//   "<file>: piece \"vamp\": no cut line on layer 1" / "2 cut lines on layer 1; a piece has one"
//   "<file>: unknown units \"Units: FURLONG\" (METRIC, MM, CM, ENGLISH or INCH)"
//   "<file>: piece \"vamp\": quantity 'two' is not a positive count"
#include <filesystem>
#include <string>
#include <vector>

#include "engine/pattern/pattern_piece.hpp"

namespace lastcut {

// The whole file. Throws EngineError ("DXF-AAMA: piece \"X\": ...") for a piece it cannot write:
// no name, a cut line of fewer than 3 points or clockwise, a quantity below 1, a non-finite
// coordinate, a line of fewer than 2 points, a notch without direction, a label outside ASCII.
std::string aama_dxf_text(const std::vector<PatternPiece>& pieces);

// aama_dxf_text written durably (engine/core/durable_file.hpp). Throws EngineError naming the file.
void write_aama_dxf(const std::filesystem::path& path, const std::vector<PatternPiece>& pieces);

// The pieces of a DXF-AAMA file; throws EngineError (one line naming the file) as described above.
std::vector<PatternPiece> read_aama_dxf(const std::filesystem::path& path);
// The same for a file's content; `file_name` names it in the refusals.
std::vector<PatternPiece> read_aama_dxf_text(const std::string& text, const std::string& file_name);

}  // namespace lastcut
