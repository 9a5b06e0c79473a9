#include "engine/core/svg_document.hpp"

#include <cstdio>

namespace lastcut {
namespace {

std::string micrometres(double value_mm) {
  char text[48];
  std::snprintf(text, sizeof text, "%.3f", value_mm);
  return text;
}

}  // namespace

std::string svg_document_start(const SvgViewBox& view_box, int display_width_px, std::string_view extra_attributes) {
  std::string size;
  if (display_width_px > 0) {
    size = "width=\"" + std::to_string(display_width_px) + "\"";
  } else {
    size = "width=\"" + micrometres(view_box.width_mm) + "mm\" height=\"" + micrometres(view_box.height_mm) + "mm\"";
  }
  std::string start = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" " + size +
                      " viewBox=\"" + micrometres(view_box.x_mm) + " " + micrometres(view_box.y_mm) + " " +
                      micrometres(view_box.width_mm) + " " + micrometres(view_box.height_mm) + "\"";
  if (!extra_attributes.empty()) start += " " + std::string(extra_attributes);
  return start + ">\n";
}

std::string xml_escaped(std::string_view text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (char c : text) {
    if (c == '<') escaped += "&lt;";
    else if (c == '>') escaped += "&gt;";
    else if (c == '&') escaped += "&amp;";
    else if (c == '"') escaped += "&quot;";
    else escaped += c;
  }
  return escaped;
}

}  // namespace lastcut
