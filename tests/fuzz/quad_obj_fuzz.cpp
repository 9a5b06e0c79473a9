// Fuzz target: the quad OBJ reader of `lastcut subdivide` (engine/subdiv/quad_obj.hpp), then the
// manifold checks and the Bezier sampling at n = 2 on what it read. The control mesh comes from
// people and other programs: outside input. Only EngineError (the one-line refusal) is caught; see
// mesh_fuzz.hpp for why anything else must be reported as a crash.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "engine/subdiv/quad_obj.hpp"
#include "engine/subdiv/sample_surface.hpp"
#include "engine_file_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return lastcut::fuzz::read_engine_file(data, size, "quads.obj", [](const std::filesystem::path& path) {
    const lastcut::QuadMesh control = lastcut::read_quad_obj(path);
    lastcut::subdivide_bezier(control, 2, lastcut::SampleSpread::EvenAtExtraordinary);
  });
}
