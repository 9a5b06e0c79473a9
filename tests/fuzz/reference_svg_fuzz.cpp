// Fuzz target: reading a reference pattern as SVG (engine/compare/reference_outline.hpp), what
// lastcutd does when a job's sidecar names a reference pattern (daemon/station/reference_check.cpp)
// and what `lastcut compare MOLD REFERENCE` does: read_reference_outline parses the file and refuses
// sizes and shapes no shoe pattern has (check_pattern_outline). The comparison itself is left out:
// under the sanitizers one of real patterns takes 1-6 s (Clipper, at every trial motion of the
// alignment); the target `compare` fuzzes it on small outlines made from the bytes directly.
//
// What counts as fine: read_reference_outline documents EngineError, one line, for a file that is not
// a usable pattern; the daemon then fails the job with that line. Any other exception surfaces as a
// libFuzzer crash, as do sanitizer reports, hangs and out-of-memory.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "engine/compare/reference_outline.hpp"
#include "engine_file_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return lastcut::fuzz::read_engine_file(data, size, "reference.svg", [](const std::filesystem::path& path) {
    (void)lastcut::read_reference_outline(path);
  });
}
