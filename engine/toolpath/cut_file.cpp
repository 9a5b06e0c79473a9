#include "engine/toolpath/cut_file.hpp"

#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/toolpath/dxf_writer.hpp"
#include "engine/toolpath/gcode_writer.hpp"
#include "engine/toolpath/hpgl_writer.hpp"
#include "engine/toolpath/svg_writer.hpp"

namespace lastcut {

std::string write_cut_file(const CutProgram& program, const MachineProfile& profile, CutFileFormat format,
                           std::vector<std::size_t>* stroke_offsets) {
  switch (format) {
    case CutFileFormat::Hpgl: return write_hpgl(program, profile, stroke_offsets);
    case CutFileFormat::Gcode: return write_gcode(program, profile, stroke_offsets);
    case CutFileFormat::Dxf: return write_dxf(program);
    case CutFileFormat::Svg: return write_svg(program);
  }
  throw EngineError("unknown cut file format");
}

std::string cut_file_extension(CutFileFormat format) {
  switch (format) {
    case CutFileFormat::Hpgl: return ".plt";
    case CutFileFormat::Gcode: return ".nc";
    case CutFileFormat::Dxf: return ".dxf";
    case CutFileFormat::Svg: return ".svg";
  }
  throw EngineError("unknown cut file format");
}

void save_cut_file(const std::filesystem::path& path, const std::string& text) {
  if (Status written = write_file_durably(path, text); !written) throw EngineError(written.error());
}

}  // namespace lastcut
