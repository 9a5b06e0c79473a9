#include "engine/core/decimal_text.hpp"

#include <algorithm>
#include <charconv>

namespace lastcut {

void append_fixed(std::string& out, double value, int decimals) {
  // 309 digits before the point for DBL_MAX, a sign, the point and the decimals.
  char text[340];
  const auto written = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, std::clamp(decimals, 0, 17));
  out.append(text, written.ptr);
}

void append_integer(std::string& out, long long value) {
  char text[24];
  const auto written = std::to_chars(text, text + sizeof text, value);
  out.append(text, written.ptr);
}

std::string fixed_text(double value, int decimals) {
  std::string text;
  append_fixed(text, value, decimals);
  return text;
}

}  // namespace lastcut
