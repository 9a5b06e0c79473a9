#include "engine/core/svg_document.hpp"

#include <cstdio>

namespace lastcut {

std::string svg_number_mm(double value_mm) {
  char text[48];
  std::snprintf(text, sizeof text, "%.3f", value_mm);
  return text;
}

std::string svg_document_start(const SvgViewBox& view_box, int display_width_px, std::string_view extra_attributes) {
  std::string size;
  if (display_width_px > 0) {
    size = "width=\"" + std::to_string(display_width_px) + "\"";
  } else {
    size = "width=\"" + svg_number_mm(view_box.width_mm) + "mm\" height=\"" + svg_number_mm(view_box.height_mm) + "mm\"";
  }
  std::string start = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" " + size +
                      " viewBox=\"" + svg_number_mm(view_box.x_mm) + " " + svg_number_mm(view_box.y_mm) + " " +
                      svg_number_mm(view_box.width_mm) + " " + svg_number_mm(view_box.height_mm) + "\"";
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
