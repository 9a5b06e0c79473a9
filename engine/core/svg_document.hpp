#pragma once
// The parts every SVG file lastcut writes has in common: the document opening (XML declaration,
// <svg> with its viewBox in mm) and text escaped for XML. The pictures themselves (molds, layouts,
// cut previews) draw their own content.
#include <string>
#include <string_view>

namespace lastcut {

// The visible area in drawing units (mm): x right, y down as SVG has it.
struct SvgViewBox {
  double x_mm = 0.0, y_mm = 0.0, width_mm = 0.0, height_mm = 0.0;
};

// XML declaration and the opening <svg ...> tag, ending in a newline. With display_width_px 0 the
// picture prints at true size (width and height in mm); otherwise it is that many pixels wide
// (large hides fit a screen). `extra_attributes` (e.g. font-family="sans-serif") go into the tag.
std::string svg_document_start(const SvgViewBox& view_box, int display_width_px = 0,
                               std::string_view extra_attributes = {});
constexpr std::string_view kSvgDocumentEnd = "</svg>\n";

// A coordinate or length in mm with 3 decimals (1 um), the resolution of lastcut's pictures.
std::string svg_number_mm(double value_mm);

// `text` with < > & " replaced by their entities, for element text and attribute values.
std::string xml_escaped(std::string_view text);

}  // namespace lastcut
