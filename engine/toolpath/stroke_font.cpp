// Glyph table: each glyph is a string of strokes separated by '|'; a stroke is a list of grid
// points "xy" (one digit each, x in 0..6, y in 0..9 upwards from the baseline) separated by spaces.
#include "engine/toolpath/stroke_font.hpp"

#include <array>
#include <cctype>
#include <string_view>
#include <utility>

namespace lastcut {
namespace {

constexpr double kCapHeightUnits = 9.0;
constexpr double kGlyphWidthUnits = 6.0;
constexpr double kAdvanceUnits = 8.0;

constexpr std::array<std::pair<char, std::string_view>, 47> kGlyphs{{
    {'0', "10 50 61 68 59 19 08 01 10|12 57"},
    {'1', "17 39 30|10 50"},
    {'2', "08 19 59 68 65 00 60"},
    {'3', "08 19 59 68 66 55 25|55 64 61 50 10 01"},
    {'4', "50 59 03 63"},
    {'5', "69 09 05 55 64 61 50 10 01"},
    {'6', "68 59 19 08 01 10 50 61 64 55 15 04"},
    {'7', "09 69 20"},
    {'8', "15 06 08 19 59 68 66 55 15 04 01 10 50 61 64 55"},
    {'9', "65 54 14 05 08 19 59 68 61 50 10 01"},
    {'A', "00 39 60|13 53"},
    {'B', "00 09 59 68 66 55 05|55 64 61 50 00"},
    {'C', "68 59 19 08 01 10 50 61"},
    {'D', "00 09 49 67 62 40 00"},
    {'E', "60 00 09 69|05 45"},
    {'F', "00 09 69|05 45"},
    {'G', "68 59 19 08 01 10 50 61 64 34"},
    {'H', "00 09|60 69|05 65"},
    {'I', "10 50|19 59|30 39"},
    {'J', "19 69|59 51 40 10 01 02"},
    {'K', "00 09|69 04|25 60"},
    {'L', "09 00 60"},
    {'M', "00 09 34 69 60"},
    {'N', "00 09 60 69"},
    {'O', "10 50 61 68 59 19 08 01 10"},
    {'P', "00 09 59 68 65 54 04"},
    {'Q', "10 50 61 68 59 19 08 01 10|33 60"},
    {'R', "00 09 59 68 65 54 04|34 60"},
    {'S', "68 59 19 08 06 15 55 64 61 50 10 01"},
    {'T', "09 69|39 30"},
    {'U', "09 01 10 50 61 69"},
    {'V', "09 30 69"},
    {'W', "09 10 35 50 69"},
    {'X', "00 69|09 60"},
    {'Y', "09 35 69|35 30"},
    {'Z', "09 69 00 60"},
    {'-', "14 54"},
    {'+', "14 54|32 36"},
    {'.', "30 31"},
    {'/', "00 69"},
    {':', "32 33|36 37"},
    {'(', "49 27 22 40"},
    {')', "29 47 42 20"},
    {'=', "13 53|16 56"},
    {'_', "00 60"},
    {'?', "08 19 59 68 66 55 35 33|30 31"},
    {'#', "13 63|16 66|20 29|40 49"},
}};

std::string_view glyph_for(char c) {
  const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const auto& [key, strokes] : kGlyphs) {
    if (key == upper) return strokes;
  }
  return glyph_for('?');
}

}  // namespace

double text_width_mm(const std::string& text, double height_mm) {
  if (text.empty()) return 0.0;
  const double units = kAdvanceUnits * static_cast<double>(text.size() - 1) + kGlyphWidthUnits;
  return units * height_mm / kCapHeightUnits;
}

std::vector<std::vector<Point2>> text_strokes(const std::string& text, const Point2& center_mm, double height_mm) {
  std::vector<std::vector<Point2>> strokes;
  const double scale = height_mm / kCapHeightUnits;
  const Point2 origin_mm = center_mm - Point2(0.5 * text_width_mm(text, height_mm), 0.5 * height_mm);
  for (size_t index = 0; index < text.size(); ++index) {
    if (text[index] == ' ') continue;
    const double advance_mm = kAdvanceUnits * scale * static_cast<double>(index);
    std::vector<Point2> stroke;
    const std::string_view glyph = glyph_for(text[index]);
    for (size_t i = 0; i <= glyph.size(); ++i) {
      if (i == glyph.size() || glyph[i] == '|') {
        if (stroke.size() >= 2) strokes.push_back(stroke);
        stroke.clear();
      } else if (std::isdigit(static_cast<unsigned char>(glyph[i])) && i + 1 < glyph.size()) {
        const double x_units = glyph[i] - '0';
        const double y_units = glyph[i + 1] - '0';
        stroke.push_back(origin_mm + Point2(advance_mm + x_units * scale, y_units * scale));
        ++i;
      }
    }
  }
  return strokes;
}

}  // namespace lastcut
