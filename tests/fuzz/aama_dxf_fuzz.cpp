// Fuzz target: the DXF-AAMA pattern reader (engine/pattern/aama_dxf.hpp), what lastcut does with a
// pattern file from pattern CAD: read_aama_dxf, which parses the DXF (HEADER, BLOCKS with their
// POLYLINE/LWPOLYLINE, LINE, POINT and TEXT entities, INSERTs of ENTITIES, bulges, $INSUNITS) and
// reads each inserted block as a piece (one closed cut line on layer 1, the system texts, notches,
// grain line, drawn lines, the units).
//
// What counts as fine: read_aama_dxf documents EngineError for a file that is not a usable pattern.
// Any other exception is not caught, so it surfaces as a libFuzzer crash, as do sanitizer reports,
// hangs and out-of-memory.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "engine/pattern/aama_dxf.hpp"
#include "engine_file_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return lastcut::fuzz::read_engine_file(data, size, "pattern.dxf", [](const std::filesystem::path& path) {
    (void)lastcut::read_aama_dxf(path);
  });
}
