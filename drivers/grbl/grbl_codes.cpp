// Tables of grbl 1.1 error and alarm codes (gnea/grbl doc/csv/*_codes_en_US.csv).
#include "drivers/grbl/grbl_codes.hpp"

#include <array>
#include <string_view>
#include <utility>

namespace lastcut::drivers::grbl {

namespace {

constexpr std::array<std::pair<int, std::string_view>, 36> kErrors{{
    {1, "Expected command letter: a G-code word has no letter"},
    {2, "Bad number format: missing or malformed number in the line"},
    {3, "Invalid statement: '$' system command not recognized"},
    {4, "Value < 0: negative value for a value that must be positive"},
    {5, "Setting disabled: homing cycle requested but homing is not enabled"},
    {6, "Value < 3 usec: minimum step pulse time must be greater than 3 usec"},
    {7, "EEPROM read fail: settings restored to defaults"},
    {8, "Not idle: '$' command only allowed when grbl is idle"},
    {9, "G-code lock: G-code is locked out during alarm or jog state"},
    {10, "Homing not enabled: soft limits need homing enabled"},
    {11, "Line overflow: too many characters in the line; it was not executed"},
    {12, "Step rate > 30kHz: setting would exceed the maximum step rate"},
    {13, "Check door: safety door is open"},
    {14, "Line length exceeded: startup or build info line too long for EEPROM"},
    {15, "Travel exceeded: jog target exceeds machine travel; jog ignored"},
    {16, "Invalid jog command: no '=' or prohibited G-code in jog"},
    {17, "Setting disabled: laser mode requires PWM output"},
    {20, "Unsupported command: unsupported or invalid G-code command in the line"},
    {21, "Modal group violation: two commands of the same modal group in one line"},
    {22, "Undefined feed rate: feed rate has not been set"},
    {23, "Invalid G-code: command requires an integer value"},
    {24, "Invalid G-code: more than one command in the line needs axis words"},
    {25, "Invalid G-code: repeated word in the line"},
    {26, "Invalid G-code: no axis words for a command that needs them"},
    {27, "Invalid G-code: line number value is invalid"},
    {28, "Invalid G-code: command is missing a required value word"},
    {29, "Invalid G-code: G59.x work coordinate systems are not supported"},
    {30, "Invalid G-code: G53 only allowed with G0 and G1"},
    {31, "Invalid G-code: axis words in a line that does not use them"},
    {32, "Invalid G-code: G2/G3 arcs need at least one in-plane axis word"},
    {33, "Invalid G-code: motion target is invalid"},
    {34, "Invalid G-code: arc radius is invalid"},
    {35, "Invalid G-code: G2/G3 arcs need at least one in-plane offset word"},
    {36, "Invalid G-code: unused value words in the line"},
    {37, "Invalid G-code: G43.1 offset not on the tool length axis"},
    {38, "Invalid G-code: tool number greater than supported"},
}};

constexpr std::array<std::pair<int, std::string_view>, 10> kAlarms{{
    {1, "Hard limit triggered: position is likely lost, re-homing is highly recommended"},
    {2, "Soft limit: motion target exceeds machine travel; position retained, alarm may be unlocked"},
    {3, "Reset while in motion: position not guaranteed, re-homing is highly recommended"},
    {4, "Probe fail: probe not in the expected initial state"},
    {5, "Probe fail: probe did not contact the workpiece within travel"},
    {6, "Homing fail: reset during the homing cycle"},
    {7, "Homing fail: safety door opened during homing"},
    {8, "Homing fail: could not clear the limit switch when pulling off"},
    {9, "Homing fail: limit switch not found within search distance"},
    {10, "Homing fail: second limit switch of a dual axis not found"},
}};

template <size_t N>
std::string lookup(const std::array<std::pair<int, std::string_view>, N>& table, int code, const char* kind) {
  for (const auto& [number, text] : table) {
    if (number == code) return std::string(text);
  }
  return std::string("unknown ") + kind + " code " + std::to_string(code);
}

}  // namespace

std::string error_meaning(int code) { return lookup(kErrors, code, "error"); }
std::string alarm_meaning(int code) { return lookup(kAlarms, code, "alarm"); }

}  // namespace lastcut::drivers::grbl
