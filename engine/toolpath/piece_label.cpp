#include "engine/toolpath/piece_label.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "engine/toolpath/planar_geometry.hpp"
#include "engine/toolpath/stroke_font.hpp"

namespace lastcut {
namespace {

std::string upper(std::string word) {
  for (char& c : word) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return word;
}

// The text box (with a clearance of a quarter letter around it) lies inside the outline and
// crosses none of its edges.
bool box_fits(const Point2& center_mm, double width_mm, double height_mm, const Polygon2& outline) {
  const double margin_mm = 0.25 * height_mm;
  const Point2 half(0.5 * width_mm + margin_mm, 0.5 * height_mm + margin_mm);
  const Point2 corners[4] = {center_mm + Point2(-half.x(), -half.y()), center_mm + Point2(half.x(), -half.y()),
                             center_mm + Point2(half.x(), half.y()), center_mm + Point2(-half.x(), half.y())};
  for (const Point2& corner : corners) {
    if (!point_in_ring(corner, outline.points)) return false;
  }
  const auto& p = outline.points;
  for (size_t i = 0; i < p.size(); ++i) {
    for (int side = 0; side < 4; ++side) {
      if (segments_touch(p[i], p[(i + 1) % p.size()], corners[side], corners[(side + 1) % 4])) return false;
    }
  }
  return true;
}

}  // namespace

std::string piece_marking(int order, const std::string& item_label) {
  if (item_label.starts_with('#')) return std::to_string(order) + " " + item_label;
  std::string size;
  std::string side;
  std::istringstream words(item_label);
  std::string word;
  while (words >> word) {
    const std::string big = upper(word);
    if (side.empty() && (big == "L" || big == "LEFT")) side = "L";
    if (side.empty() && (big == "R" || big == "RIGHT")) side = "R";
    if (size.empty() && std::any_of(word.begin(), word.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
      for (char c : word) {
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') size += c;
      }
    }
  }
  std::string text = std::to_string(order);
  if (!size.empty()) text += " " + size;
  if (!side.empty()) text += " " + side;
  return text;
}

std::optional<PlacedText> place_text(const std::string& text, const Polygon2& outline, double height_mm,
                                     double min_height_mm) {
  if (text.empty() || outline.points.size() < 3) return std::nullopt;
  Point2 low = outline.points.front(), high = outline.points.front();
  for (const Point2& point : outline.points) {
    low = low.cwiseMin(point);
    high = high.cwiseMax(point);
  }
  constexpr int kGrid = 24;
  std::vector<std::pair<double, Point2>> candidates;  // (clearance mm, centre)
  for (int i = 1; i < kGrid; ++i) {
    for (int j = 1; j < kGrid; ++j) {
      const Point2 center = low + Point2((high.x() - low.x()) * i / kGrid, (high.y() - low.y()) * j / kGrid);
      if (point_in_ring(center, outline.points)) candidates.emplace_back(distance_to_boundary(center, outline), center);
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) {
    if (a.first != b.first) return a.first > b.first;
    return a.second.x() != b.second.x() ? a.second.x() < b.second.x() : a.second.y() < b.second.y();
  });
  constexpr size_t kTried = 40;
  if (candidates.size() > kTried) candidates.resize(kTried);
  for (double height = height_mm; height >= min_height_mm - 1e-9; height *= 0.8) {
    const double width = text_width_mm(text, height);
    for (const auto& [clearance_mm, center] : candidates) {
      if (clearance_mm < 0.5 * height) break;
      if (box_fits(center, width, height, outline)) return PlacedText{center, height};
    }
  }
  return std::nullopt;
}

}  // namespace lastcut
