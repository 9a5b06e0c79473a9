// Fuzz target: the machine profile parser (engine/toolpath/machine_profile.hpp),
// parse_machine_profile on TOML text. Profiles (config/machines/*.toml) are written by whoever
// sets up a cutter, and name the feeds, tools and cut-file format of every job sent to it.
//
// What counts as fine: parse_machine_profile documents EngineError for a bad profile (TOML syntax,
// unknown key, bad value), and the command line and daemon catch exactly that. Any other
// exception is not caught here, so it surfaces as a libFuzzer crash, as do sanitizer reports.
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/core/engine_error.hpp"
#include "engine/toolpath/machine_profile.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)lastcut::parse_machine_profile(text, "fuzz.toml");
  } catch (const lastcut::EngineError&) {
    // a refusal with one line for the operator
  }
  return 0;
}
