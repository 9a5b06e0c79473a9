#pragma once
// place_hide: a hide file is named as lying on a cutter's table. The one way a hide reaches
// paths.hides besides a digitizer dropping it there: `lastcut hide load` (from the stock folder)
// and the operator page's upload both come through here. The file is read and checked first (a
// bad hide is refused with the reader's line and nothing is written); then its sidecar naming the
// cutter is written, then the hide itself, both durably, so lastcutd never sees the hide without
// its cutter. The source file stays where it is.
#include <filesystem>
#include <string>

#include "daemon/config/daemon_config.hpp"
#include "engine/core/status.hpp"

namespace lastcut::daemon {

// `source`: a .dxf or .json hide file; `file_name`: its name in paths.hides; `written_by`: who,
// for the sidecar's comment ("`lastcut hide load X --cutter C`", "the operator page (token anna)").
// The line to log ("hide H (file, 2.31 m^2) now lies on cutter C: path"), or why not.
Result<std::string> place_hide(const DaemonConfig& config, const std::filesystem::path& source,
                               const std::string& file_name, const std::string& cutter, const std::string& written_by);

}  // namespace lastcut::daemon
