// Fuzz target: the scan-to-molds pipeline (engine/scan/scan_to_molds.hpp) on an OFF scan of
// a whole last: read, orient, segment into medial and lateral halves, flatten
// each, make the molds. The mesh-reader targets stop where the reader accepts a file; this one goes on
// into the geometry with what mutations of a valid seed make of it: moved, duplicated or collapsed
// vertices, folds, spikes, slivers. What counts as fine: see scan_fuzz.hpp.
#include "scan_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return lastcut::fuzz::fuzz_scan_to_molds(data, size, /*segment=*/true);
}
