#include "engine/toolpath/cut_job.hpp"

#include "engine/core/engine_error.hpp"
#include "engine/toolpath/cut_file.hpp"

namespace lastcut {

CutFile make_cut_file(const Layout& layout, const NestInstance& instance, const MachineProfile& profile,
                      const CutFileRequest& request) {
  const std::vector<PlacedPiece> pieces = placed_pieces(layout, instance, request.sheet);
  if (pieces.empty()) throw EngineError("the layout places no pieces on this sheet: nothing to cut");
  CutFile file;
  file.format = request.format.value_or(profile.native_format);
  file.program = plan_cut_program(pieces, profile, request.order);
  file.program.notes = request.notes;
  file.text = write_cut_file(file.program, profile, file.format, &file.stroke_offsets);
  file.stats = measure_program(file.program);
  return file;
}

}  // namespace lastcut
