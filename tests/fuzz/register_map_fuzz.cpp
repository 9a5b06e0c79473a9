// Fuzz target: the Modbus register-map file (drivers/modbus/register_map.hpp), load_register_map
// then validate_register_map and register_count, in the order the Modbus driver uses them. The
// map (config/modbus-register-map.toml) is copied and edited by the integrator of a PLC-driven
// cutter: outside input.
//
// What counts as fine: both functions return false with a message for a bad map. They document
// no exception, so none is caught here: any throw, crash or sanitizer report (e.g. an int
// overflow in the register arithmetic, under UBSan) surfaces as a libFuzzer crash.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "drivers/modbus/register_map.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static lastcut::fuzz::FuzzInputFile file("modbus-register-map.toml");
  lastcut::drivers::modbus::RegisterMap map;
  std::string error;
  if (!lastcut::drivers::modbus::load_register_map(file.write(data, size).string(), map, error)) {
    if (error.empty()) std::abort();  // a refusal must say why
    return 0;
  }
  if (lastcut::drivers::modbus::validate_register_map(map, error)) {
    if (map.register_count() <= 0) std::abort();  // a valid map needs at least one register
  } else if (error.empty()) {
    std::abort();
  }
  return 0;
}
