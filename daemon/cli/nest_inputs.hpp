#pragma once
// What `lastcut nest` is given besides a nest instance JSON: mold DXFs written by `lastcut flatten`
// (or folders of them) and DXF-AAMA pattern sets from a pattern room (engine/pattern/aama_dxf.hpp).
//
// Both are `.dxf`, so the file's content decides, not its name. `lastcut flatten` draws its mold as
// plain entities in ENTITIES (layers CUT, MARK, LABEL, NET) and never writes a block; DXF-AAMA puts
// every piece in a BLOCK (its cut line on layer 1) and places it with an INSERT. A file is a pattern
// set when its ENTITIES place a block or a block draws on layer 1 (a set whose INSERTs are missing
// then gets the pattern reader's refusal, not the mold reader's); anything else is read as a mold,
// and a file the DXF reader cannot parse gets the mold reader's refusal, as before pattern sets.
#include <filesystem>
#include <string>
#include <vector>

#include "engine/mold/mold.hpp"
#include "engine/pattern/pattern_piece.hpp"

namespace lastcut::cli {

struct NestInputs {
  std::vector<Mold> molds;                  // named "FOLDER HALF" (whose last, which half)
  std::vector<PatternPiece> pattern_pieces;  // every pattern set's pieces, in input order
};

// True when the DXF at `path` follows the DXF-AAMA convention (see above).
bool is_pattern_set(const std::filesystem::path& path);

// Each input is a `.dxf` file or a folder whose `.dxf` files (sorted by name) are read. Throws
// EngineError with the readers' one-line refusals, or for a folder without `.dxf` files.
NestInputs read_nest_inputs(const std::vector<std::string>& inputs);

}  // namespace lastcut::cli
