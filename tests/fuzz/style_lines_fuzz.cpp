// Fuzz target: style lines as OBJ polylines (engine/style/style_lines_obj.hpp), read_style_lines_obj on a
// lines.obj file. Pattern makers export these from any 3D CAD program (Rhino, Blender, MeshLab) and
// ship them in style folders: outside input, read by `lastcut style pieces`, `style check` and `style
// transfer`.
//
// What counts as fine: read_style_lines_obj documents EngineError (one line naming the file and line: a
// face, a number that is not one, an index out of range, a line of fewer than two points, no lines, two
// lines of one name). Any other exception is not caught, so it surfaces as a libFuzzer crash, as do
// sanitizer reports.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "engine/style/style_lines_obj.hpp"
#include "engine_file_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return lastcut::fuzz::read_engine_file(data, size, "lines.obj",
                                         [](const std::filesystem::path& path) { lastcut::read_style_lines_obj(path); });
}
