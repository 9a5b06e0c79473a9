#pragma once
// The body shared by the four mesh-reader targets (stl, obj, ply, off): the scan is read the way
// the daemon reads every file dropped in its watch folder, read_mesh on the file (format by
// extension, OpenMesh's parser behind lastcut's own file checks), then check_is_last.
//
// What counts as fine: read_mesh and check_is_last document lastcut::EngineError as their one
// refusal ("truncated binary STL ...", "not a shoe last: ..."); the daemon catches exactly that
// per job. Any other exception (std::bad_alloc, std::length_error, an Eigen or OpenMesh
// exception) would escape the daemon's per-job handler, so it is not caught here: libFuzzer
// reports it as a crash, as it does sanitizer reports.
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/core/engine_error.hpp"
#include "engine/mesh/read_mesh.hpp"
#include "fuzz_input_file.hpp"

namespace lastcut::fuzz {

inline int fuzz_mesh_reader(const uint8_t* data, size_t size, const std::string& file_name) {
  static FuzzInputFile file(file_name);
  MeshReadOptions options;
  options.max_triangles = 200'000;  // a bound the fuzzer can reach; the real cap is only larger
  try {
    const MeshIntake intake = read_mesh(file.write(data, size), options);
    check_is_last(intake.mesh);
  } catch (const EngineError&) {
    // a refusal with one line for the operator: the expected outcome for most inputs
  }
  return 0;
}

}  // namespace lastcut::fuzz
