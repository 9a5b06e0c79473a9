// Fuzz target: the nesting instance reader (engine/nest/nest_json.hpp), read_nest_instance on a
// JSON file, as `lastcut nest INSTANCE.json` reads it. Instances come from benchmark sets
// (ESICUP, jagua-rs) and from other programs: outside input.
//
// What counts as fine: read_nest_instance documents EngineError for every bad file (not JSON,
// missing fields, fewer than 3 points, zero area, non-finite numbers, duplicate ids), and the
// command line catches exactly that. An nlohmann::json exception escaping (a type_error from a
// field read with the wrong type) would be a bug of the reader, so it is not caught here; nor is
// anything else: it surfaces as a libFuzzer crash, as do sanitizer reports.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "engine/nest/nest_json.hpp"
#include "engine_file_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return lastcut::fuzz::read_engine_file(data, size, "instance.json", [](const std::filesystem::path& path) {
    (void)lastcut::read_nest_instance(path);
  });
}
