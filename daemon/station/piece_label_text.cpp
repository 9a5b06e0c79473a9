#include "daemon/station/piece_label_text.hpp"

#include <filesystem>

namespace lastcut::daemon {
namespace {

std::string without_spaces(std::string text, char replacement) {
  std::string out;
  for (char c : text) {
    if (c == ' ' || c == '\t') {
      if (replacement) out += replacement;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

std::string opposite_foot(const std::string& foot) {
  if (foot == "left") return "right";
  if (foot == "right") return "left";
  return foot;
}

std::string piece_label_text(const PieceLabelParts& parts) {
  std::string reference = parts.order.empty() ? std::filesystem::path(parts.scan_name).stem().string() : parts.order;
  reference = without_spaces(reference, '-').substr(0, kMaxReferenceChars);
  std::string label = "#" + (reference.empty() ? std::string("?") : reference);
  if (!parts.size.empty()) label += " " + without_spaces(parts.size, '\0');
  if (parts.foot == "left") label += " L";
  if (parts.foot == "right") label += " R";
  if (parts.part == "medial") label += " med";
  else if (parts.part == "lateral") label += " lat";
  else if (!parts.part.empty()) label += " " + without_spaces(parts.part, '-');
  return label;
}

}  // namespace lastcut::daemon
