#pragma once
// The body shared by scan_last and scan_patch: scan_to_molds (engine/scan/scan_to_molds.hpp) on the
// input as an OFF scan in mm, with or without segmentation, the triangle count capped at 5000 so that
// one input takes milliseconds. scan_to_molds documents EngineError (one line) as its refusal; the
// daemon fails the job with it. Any other exception is a crash here (lastcutd would fail the job with it
// as an internal error, but it is a bug all the same), as are sanitizer reports, hangs and out-of-memory.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "engine/scan/scan_to_molds.hpp"
#include "engine_file_fuzz.hpp"

namespace lastcut::fuzz {

inline int fuzz_scan_to_molds(const uint8_t* data, size_t size, bool segment) {
  return read_engine_file(data, size, "scan.off", [segment](const std::filesystem::path& path) {
    ScanOptions options;
    options.segment = segment;
    options.read.unit = LengthUnit::Millimetre;
    options.read.max_triangles = 5000;
    (void)scan_to_molds(path, options);
  });
}

}  // namespace lastcut::fuzz
