#pragma once
// The files a style's pieces on one last leave behind, for `lastcut pieces` and the daemon's style
// jobs alike (the contract other tools read):
//   OUT/PIECE.dxf        cut line, notches, net line, label (the mold DXF: `lastcut nest OUT` reads them)
//   OUT/PIECE.svg        the piece over its stretch
//   OUT/aama/STYLE-SIZE-FOOT.dxf   every piece as DXF-AAMA (engine/pattern), for pattern CAD
//   OUT/pieces.json      per piece: material, quantity, areas, distortion, edges, notches, grain line;
//                        per seam: its length on the pieces of both sides; written last, durably
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/style/style_pieces.hpp"

namespace lastcut {

struct PieceOutputsInfo {
  std::string scan;  // the scan's name, in the report
  std::string size;  // the size label ("42"), "" when unknown
  std::string foot;  // "left" or "right"
};

// Creates out_dir if needed and returns the report it wrote as pieces.json. Throws EngineError when a
// file cannot be written.
nlohmann::json write_piece_outputs(const StyleDefinition& style, const StyleResult& result, const PieceOutputsInfo& info,
                                   const std::filesystem::path& out_dir);

// A file name for a piece: letters, digits and '-' kept, anything else '-'.
std::string piece_file_stem(const std::string& piece);

}  // namespace lastcut
