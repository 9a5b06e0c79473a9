#pragma once
// CutMap: where each piece of a cut file lies on the table and which bytes of the file cut it, so
// whoever follows a running cut (the operator page) can tell from the bytes the cutter has taken
// which piece the knife is on, which are cut and which wait. Written beside the cut file as
// cut-map.json. The bytes are the file's; a machine's input buffer may hold a few moves more than
// it has cut, so "the piece being cut" is the piece whose bytes are being sent.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/polygon.hpp"
#include "engine/toolpath/cut_job.hpp"

namespace lastcut {

struct CutMapPiece {
  std::string label;    // the layout item's label (order, piece name)
  std::string marking;  // the text drawn on it, "" when none
  std::size_t first_byte = 0, end_byte = 0;  // [first, end) of the cut file: every stroke of this piece
  Polygon2 outline_mm;  // placed on the table, mm
};

struct CutMap {
  std::size_t bytes_total = 0;
  double table_x_mm = 0, table_y_mm = 0;  // the machine's work area
  std::vector<CutMapPiece> pieces;        // in cutting order
};

// Empty pieces when the file's format records no stroke offsets (DXF, SVG).
CutMap make_cut_map(const CutFile& file);

// {"bytes_total", "table_mm": [x, y], "pieces": [{"label", "marking", "first_byte", "end_byte",
//  "outline_mm": [[x, y], ...]}]}, outlines rounded to 0.1 mm.
nlohmann::json to_json(const CutMap& map);

}  // namespace lastcut
