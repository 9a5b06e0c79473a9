// Parsing of --fault options for the simulated devices.
#include <charconv>

#include "drivers/sim/byte_device.hpp"

namespace lastcut::drivers::sim {

namespace {

bool parse_size(std::string_view text, size_t& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size() && value > 0;
}

}  // namespace

bool parse_fault(const std::string& text, Faults& faults, std::string& error) {
  const auto equals = text.find('=');
  if (equals == std::string::npos) {
    error = "fault '" + text + "' needs KIND=LINE";
    return false;
  }
  const std::string kind = text.substr(0, equals);
  std::string_view value = std::string_view(text).substr(equals + 1);
  int code = -1;
  if (const auto colon = value.find(':'); colon != std::string_view::npos) {
    const auto code_text = value.substr(colon + 1);
    const auto [end, ec] = std::from_chars(code_text.data(), code_text.data() + code_text.size(), code);
    if (ec != std::errc() || end != code_text.data() + code_text.size()) {
      error = "fault '" + text + "': bad code";
      return false;
    }
    value = value.substr(0, colon);
  }
  size_t line = 0;
  if (!parse_size(value, line)) {
    error = "fault '" + text + "': line must be a positive number";
    return false;
  }
  if (kind == "drop-at-line") faults.drop_at_line = line;
  else if (kind == "stall-at-line") faults.stall_at_line = line;
  else if (kind == "freeze-at-line") faults.freeze_at_line = line;
  else if (kind == "garbage-at-line") faults.garbage_at_line = line;
  else if (kind == "error-at-line") {
    faults.error_at_line = line;
    if (code >= 0) faults.error_code = code;
  } else if (kind == "alarm-at-line") {
    faults.alarm_at_line = line;
    if (code >= 0) faults.alarm_code = code;
  } else {
    error = "unknown fault '" + kind + "' (drop-at-line, stall-at-line, freeze-at-line, garbage-at-line, error-at-line, alarm-at-line)";
    return false;
  }
  return true;
}

}  // namespace lastcut::drivers::sim
