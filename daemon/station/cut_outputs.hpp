#pragma once
// What a batch or a hide keeps of its cut file, written the same way for both: the file the cutter
// receives (cut.plt or cut.nc), its picture (preview.svg) and its map (cut-map.json: each piece's
// place on the table and its bytes in the file, which the operator page follows during the cut).
#include <filesystem>
#include <string>

#include "engine/core/status.hpp"
#include "engine/toolpath/cut_job.hpp"

namespace lastcut::daemon {

inline constexpr const char* kCutMapFile = "cut-map.json";

// Writes the three files into `dir` durably; the cut file's name, or why not.
Result<std::string> write_cut_outputs(const std::filesystem::path& dir, const CutFile& cut);

}  // namespace lastcut::daemon
