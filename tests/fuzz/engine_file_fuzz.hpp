#pragma once
// The body shared by the targets whose engine entry reads a file and refuses bad input with
// lastcut::EngineError (one line for the operator): the input is written to a file of the name the
// entry expects (FuzzInputFile) and handed to `read`. That refusal is the expected outcome for most
// inputs; any other exception is not caught, so libFuzzer reports it as a crash, as it does sanitizer
// reports, hangs and out-of-memory (docs/fuzzing.md).
//
//   extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
//     return lastcut::fuzz::read_engine_file(data, size, "hide.json",
//                                            [](const std::filesystem::path& p) { lastcut::read_hide_file(p); });
//   }
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "engine/core/engine_error.hpp"
#include "fuzz_input_file.hpp"

namespace lastcut::fuzz {

// One FuzzInputFile per target process (each target has one file name).
template <typename Read>
int read_engine_file(const uint8_t* data, size_t size, const std::string& file_name, Read&& read) {
  static FuzzInputFile file(file_name);
  try {
    read(file.write(data, size));
  } catch (const EngineError&) {
    // a refusal with one line for the operator
  }
  return 0;
}

}  // namespace lastcut::fuzz
