#include "drivers/grbl/axis_words.hpp"

#include <cctype>

namespace lastcut::drivers::grbl {

namespace {

constexpr std::string_view kAxisOrder = "XYZABCUVW";

bool starts_number(const std::string& line, size_t at) {
  while (at < line.size() && line[at] == ' ') ++at;  // grbl ignores spaces inside words
  return at < line.size() && (std::isdigit(static_cast<unsigned char>(line[at])) || line[at] == '-' ||
                              line[at] == '+' || line[at] == '.');
}

}  // namespace

std::string axis_letters(int axis_count) {
  if (axis_count <= 0) return "";
  return std::string(kAxisOrder.substr(0, static_cast<size_t>(axis_count)));
}

std::string check_axis_words(const std::vector<std::string>& lines, int axis_count) {
  const std::string allowed = axis_letters(axis_count);
  for (size_t index = 0; index < lines.size(); ++index) {
    const std::string& line = lines[index];
    if (!line.empty() && line[0] == '$') continue;  // system commands have no axis words
    bool in_comment = false;
    for (size_t at = 0; at < line.size(); ++at) {
      const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(line[at])));
      if (c == ';') break;
      if (c == '(') in_comment = true;
      if (c == ')') in_comment = false;
      if (in_comment || kAxisOrder.find(c) == std::string_view::npos || !starts_number(line, at + 1)) continue;
      if (allowed.find(c) != std::string::npos) continue;
      std::string have;
      for (char axis : allowed) have += std::string(have.empty() ? "" : " ") + axis;
      return "line " + std::to_string(index + 1) + " moves the " + std::string(1, c) + " axis, but the controller has " +
             std::to_string(axis_count) + " axes (" + have + ")";
    }
  }
  return "";
}

}  // namespace lastcut::drivers::grbl
