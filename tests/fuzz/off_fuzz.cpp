// Fuzz target: the OFF reader, through read_mesh on a "scan.off" file as the daemon reads a scan
// from its watch folder. Scans come from 3D scanners and from people: the file is outside input.
// Why only EngineError is caught: see mesh_fuzz.hpp.
#include "mesh_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return lastcut::fuzz::fuzz_mesh_reader(data, size, "scan.off");
}
