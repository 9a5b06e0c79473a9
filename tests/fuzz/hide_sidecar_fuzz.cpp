// Fuzz target: a hide's sidecar (<stem>.toml beside the hide file: id, material, cutter,
// thickness_mm), read by read_hide_sidecar (engine/nest/hide_file.hpp) for every hide dropped into
// the hides folder: written by hand or by a digitizer, outside input.
//
// What counts as fine: read_hide_sidecar documents EngineError for a sidecar that is not valid TOML,
// has an unknown key or a value of the wrong kind or range; the hide then goes to failed/ with that
// line. Any other exception is not caught, so it surfaces as a libFuzzer crash, as do sanitizer reports.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "engine/nest/hide_file.hpp"
#include "engine_file_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return lastcut::fuzz::read_engine_file(data, size, "hide.toml", [](const std::filesystem::path& path) {
    lastcut::HideFile hide;
    lastcut::read_hide_sidecar(path, hide);
  });
}
