#pragma once
// Layout + machine profile -> cut program -> cut file: the one path from a nesting layout to the
// bytes a cutter receives, taken by `lastcut toolpath` and by lastcutd alike. The text returned is
// exactly what is stored and what is sent; nothing is added on the way to the machine.
#include <optional>
#include <string>
#include <vector>

#include "engine/nest/layout.hpp"
#include "engine/nest/nest_problem.hpp"
#include "engine/toolpath/cut_program.hpp"
#include "engine/toolpath/layout_pieces.hpp"
#include "engine/toolpath/machine_profile.hpp"
#include "engine/toolpath/plan_cut_program.hpp"

namespace lastcut {

struct CutFileRequest {
  SheetRef sheet;                          // which sheet of the layout (the strip: bin -1)
  std::optional<CutFileFormat> format;     // empty: the machine's own (profile.native_format)
  PieceOrder order = PieceOrder::ShortTravel;
  std::vector<std::string> notes;          // CutProgram::notes: what the program carries
};

struct CutFile {
  CutFileFormat format = CutFileFormat::Gcode;
  CutProgram program;
  std::string text;  // the file's bytes
  CutStats stats;
  // Per stroke of program.strokes, the byte of `text` where it begins, and where the last one ends
  // (HPGL and G-code: strokes + 1 entries; else empty).
  std::vector<std::size_t> stroke_offsets;
};

// Throws EngineError when the layout places nothing on the sheet or a piece cannot be planned
// (outside the machine's work area, degenerate outline).
CutFile make_cut_file(const Layout& layout, const NestInstance& instance, const MachineProfile& profile,
                      const CutFileRequest& request);

}  // namespace lastcut
