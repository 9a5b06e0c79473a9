// Fuzz target: the style folder reader (daemon/config/style_folder.hpp), read_style_folder on a folder
// whose style.toml is the input, beside a small lines.obj (three lines, vamp, counter and apron, as the
// shipped styles name them). A style folder is written by a pattern maker, copied between workshops and
// read by `lastcut style pieces` and `lastcut style check`: outside input.
//
// What counts as fine: read_style_folder returns Result<StyleFolder>; a bad style.toml is a failed Status
// with one line (every mistake, "; "-separated, naming key and line). It documents no exception, so none
// is caught here: any throw (a toml++ exception that slipped through, an EngineError from building the
// reference last's parameters, std::bad_alloc) is reported by libFuzzer as a crash. The reader only
// names a reference scan, it does not read it.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "daemon/config/style_folder.hpp"
#include "fuzz_input_file.hpp"

namespace {

constexpr const char* kLines =
    "o vamp\nv 170 -48 40\nv 184 0 0\nv 170 48 40\nl 1 2 3\n"
    "o counter\nv 0 -30 60\nv -2 0 60\nv 0 30 60\nl 4 5 6\n"
    "o apron\nv 200 -30 50\nv 250 0 35\nv 200 30 50\nl 7 8 9\n";

bool write_lines_beside(const std::filesystem::path& toml) {
  std::ofstream out(toml.parent_path() / "lines.obj", std::ios::binary | std::ios::trunc);
  out << kLines;
  if (!out) throw std::runtime_error("cannot write the fuzz target's lines.obj beside " + toml.string());
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static lastcut::fuzz::FuzzInputFile file("style.toml");
  const std::filesystem::path& toml = file.write(data, size);
  static const bool lines_written = write_lines_beside(toml);
  (void)lines_written;
  const lastcut::Result<lastcut::daemon::StyleFolder> folder = lastcut::daemon::read_style_folder(toml.parent_path());
  if (!folder && folder.error().empty()) std::abort();  // a refusal must say why
  return 0;
}
