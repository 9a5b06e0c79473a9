// write_cut_outputs (cut_outputs.hpp).
#include "daemon/station/cut_outputs.hpp"

#include "daemon/station/engine_steps.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/toolpath/cut_file.hpp"
#include "engine/toolpath/cut_map.hpp"
#include "engine/toolpath/svg_writer.hpp"

namespace lastcut::daemon {

Result<std::string> write_cut_outputs(const std::filesystem::path& dir, const CutFile& cut) {
  const std::string cut_file = "cut" + cut_file_extension(cut.format);
  if (Status written = write_file_durably(dir / cut_file, cut.text); !written) return written;
  if (Status written = write_file_durably(dir / kPreviewFile, write_svg(cut.program)); !written) return written;
  if (Status written = write_file_durably(dir / kCutMapFile, to_json(make_cut_map(cut)).dump() + "\n"); !written)
    return written;
  return cut_file;
}

}  // namespace lastcut::daemon
