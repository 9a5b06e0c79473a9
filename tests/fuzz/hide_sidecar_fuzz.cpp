// Fuzz target: a hide's sidecar (<stem>.toml beside the hide file: id, material, cutter,
// thickness_mm), read by read_hide_sidecar (engine/nest/hide_file.hpp) for every hide dropped into
// the hides folder: written by hand or by a digitizer, outside input.
//
// What counts as fine: read_hide_sidecar documents EngineError for a sidecar that is not valid TOML,
// has an unknown key or a value of the wrong kind or range; the hide then goes to failed/ with that
// line. Any other exception is not caught, so it surfaces as a libFuzzer crash, as do sanitizer reports.
#include <cstddef>
#include <cstdint>

#include "engine/core/engine_error.hpp"
#include "engine/nest/hide_file.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static lastcut::fuzz::FuzzInputFile file("hide.toml");
  lastcut::HideFile hide;
  try {
    lastcut::read_hide_sidecar(file.write(data, size), hide);
  } catch (const lastcut::EngineError&) {
    // a refusal with one line for the operator
  }
  return 0;
}
