// Fuzz target: the hide file reader (engine/nest/hide_file.hpp) on a JSON hide (the jagua-rs bin
// layout of the Baldacci instances), what lastcutd does with every file a digitizer or an operator
// drops into the hides folder: read_hide_file, which
// parses the JSON (a {"bins": [...]} instance or one bin: outer and inner rings, zones with their
// quality, units, backbone) and checks the rings (closed, simple, inside the outline, a plausible area).
//
// What counts as fine: read_hide_file documents EngineError for a file that is not a usable hide;
// the daemon moves such a file to failed/ with that one line. Any other exception is not caught,
// so it surfaces as a libFuzzer crash, as do sanitizer reports, hangs and out-of-memory.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "engine/nest/hide_file.hpp"
#include "engine_file_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return lastcut::fuzz::read_engine_file(data, size, "hide.json", [](const std::filesystem::path& path) {
    (void)lastcut::read_hide_file(path);
  });
}
