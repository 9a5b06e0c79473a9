// Fuzz target: the hide file reader (engine/nest/hide_file.hpp) on a DXF hide, what lastcutd does
// with every file a digitizer or an operator drops into the hides folder: read_hide_file, which
// parses the DXF (layers HIDE, HOLE, ZONE_<q>, BACKBONE, $INSUNITS, polyline bulges) and checks
// the rings (closed, simple, inside the outline, a plausible area).
//
// What counts as fine: read_hide_file documents EngineError for a file that is not a usable hide;
// the daemon moves such a file to failed/ with that one line. Any other exception is not caught,
// so it surfaces as a libFuzzer crash, as do sanitizer reports, hangs and out-of-memory.
#include <cstddef>
#include <cstdint>

#include "engine/core/engine_error.hpp"
#include "engine/nest/hide_file.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static lastcut::fuzz::FuzzInputFile file("hide.dxf");
  try {
    (void)lastcut::read_hide_file(file.write(data, size));
  } catch (const lastcut::EngineError&) {
    // a refusal with one line for the operator
  }
  return 0;
}
