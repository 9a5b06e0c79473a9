#pragma once
// One entry point for every cut-file format, and writing the file.
#include <filesystem>
#include <string>
#include <vector>

#include "engine/toolpath/cut_program.hpp"
#include "engine/toolpath/machine_profile.hpp"

namespace lastcut {

// The text of the cut file in `format` (HPGL, G-code, DXF or SVG).
// `stroke_offsets` (HPGL and G-code only; left empty for DXF and SVG): see write_hpgl.
std::string write_cut_file(const CutProgram& program, const MachineProfile& profile, CutFileFormat format,
                           std::vector<std::size_t>* stroke_offsets = nullptr);

// ".plt", ".nc", ".dxf" or ".svg".
std::string cut_file_extension(CutFileFormat format);

// Writes `text` to `path` durably (engine/core/durable_file.hpp), so a cutter's spool never sees
// half a file. Throws EngineError when the file cannot be written.
void save_cut_file(const std::filesystem::path& path, const std::string& text);

}  // namespace lastcut
