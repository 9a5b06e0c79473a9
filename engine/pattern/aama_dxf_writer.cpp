// Writing DXF-AAMA files (aama_dxf.hpp): the pieces checked, each drawn into its own block of an R12
// DxfDocument, the blocks placed side by side.
#include <cctype>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/durable_file.hpp"
#include "engine/core/dxf_document.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/core/polygon_centroid.hpp"
#include "engine/pattern/aama_conventions.hpp"
#include "engine/pattern/aama_dxf.hpp"

namespace lastcut {
namespace {

constexpr double kAamaTextHeight_mm = 2.5;  // Valentina's AAMA text height: small enough for a tongue
constexpr double kPieceGap_mm = 20.0;       // between neighbouring pieces of the layout

std::string piece_refusal(const PatternPiece& piece, const std::string& problem) {
  return "DXF-AAMA: piece \"" + piece.name + "\": " + problem;
}

// Texts go into the file as one DXF value line each: a line break would end the value and start
// a forged group, and the standard allows 7-bit ASCII only.
void check_label(const PatternPiece& piece, const char* what, const std::string& value) {
  for (const char c : value)
    if (c < 0x20 || c > 0x7e)
      throw EngineError(piece_refusal(piece, std::string("the ") + what +
                                                 " has a character outside printable ASCII (DXF-AAMA text is 7-bit ASCII)"));
}

void check_points(const PatternPiece& piece, const std::vector<Point2>& points, size_t minimum, const char* what) {
  if (points.size() < minimum)
    throw EngineError(piece_refusal(piece, std::string(what) + " has fewer than " + std::to_string(minimum) + " points"));
  for (const Point2& p : points)
    if (!p.allFinite()) throw EngineError(piece_refusal(piece, std::string(what) + " has a coordinate that is not finite"));
}

void check_piece(const PatternPiece& piece) {
  if (piece.name.empty()) throw EngineError("DXF-AAMA: a piece without a name");
  check_label(piece, "name", piece.name);
  check_label(piece, "style", piece.style);
  check_label(piece, "size", piece.size);
  check_label(piece, "category", piece.category);
  check_label(piece, "annotation", piece.annotation);
  if (piece.quantity < 1)
    throw EngineError(piece_refusal(piece, "quantity " + std::to_string(piece.quantity) + " is not a positive count"));
  check_points(piece, piece.cut_line_mm, 3, "its cut line");
  if (signed_area(Polygon2{piece.cut_line_mm}) <= 0.0)
    throw EngineError(piece_refusal(piece, "its cut line is clockwise or has no area; cut lines are counter-clockwise"));
  for (const auto& line : piece.internal_lines_mm) check_points(piece, line, 2, "an internal line");
  for (const auto& line : piece.sew_lines_mm) check_points(piece, line, 2, "a sew line");
  for (const PatternNotch& notch : piece.notches) {
    check_points(piece, {notch.at_mm, notch.inward}, 0, "a notch");
    if (notch.inward.norm() == 0.0) throw EngineError(piece_refusal(piece, "a notch has no inward direction"));
  }
  if (piece.grain_line_mm) check_points(piece, {(*piece.grain_line_mm)[0], (*piece.grain_line_mm)[1]}, 2, "the grain line");
}

// The block name: the piece name with what an R12 name may not hold replaced, unique in the file.
std::string block_name(const std::string& piece_name, std::set<std::string>& taken) {
  std::string name = piece_name;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '$') c = '_';
  const std::string stem = name;
  for (int n = 2; taken.count(name); ++n) name = stem + "_" + std::to_string(n);
  taken.insert(name);
  return name;
}

// An internal or sew line: one polyline, closed when it ends where it starts.
void draw_line(DxfDocument& dxf, const char* layer, const std::vector<Point2>& points_mm) {
  const bool closed = points_mm.size() > 2 && points_mm.front() == points_mm.back();
  dxf.polyline(layer, closed ? std::vector<Point2>(points_mm.begin(), points_mm.end() - 1) : points_mm, closed);
}

// The piece system text, one line under the other, around the cut line's centroid.
void draw_labels(DxfDocument& dxf, const PatternPiece& piece) {
  std::vector<std::string> lines = {std::string(aama::kPieceNameKey) + ": " + piece.name,
                                    std::string(aama::kQuantityKey) + ": " + std::to_string(piece.quantity)};
  const std::pair<const char*, const std::string*> optional[] = {{aama::kSizeKey, &piece.size},
                                                                 {aama::kStyleNameKey, &piece.style},
                                                                 {aama::kCategoryKey, &piece.category},
                                                                 {aama::kAnnotationKey, &piece.annotation}};
  for (const auto& [key, value] : optional)
    if (!value->empty()) lines.push_back(std::string(key) + ": " + *value);
  const Point2 centre = area_centroid(Polygon2{piece.cut_line_mm});
  const double line_pitch_mm = 1.6 * kAamaTextHeight_mm;
  for (size_t i = 0; i < lines.size(); ++i) {
    // Centred by an estimate of the width (0.7 h per character): no font metrics in a DXF writer.
    const double half_width_mm = 0.35 * kAamaTextHeight_mm * static_cast<double>(lines[i].size());
    const double y_mm = centre.y() + line_pitch_mm * (0.5 * static_cast<double>(lines.size()) - 1.0 - static_cast<double>(i));
    dxf.text(aama::kBoundaryLayer, Point2(centre.x() - half_width_mm, y_mm), kAamaTextHeight_mm, lines[i]);
  }
}

void draw_piece(DxfDocument& dxf, const PatternPiece& piece) {
  dxf.polyline(aama::kBoundaryLayer, piece.cut_line_mm, true);
  draw_labels(dxf, piece);
  for (const PatternNotch& notch : piece.notches) {
    const double angle_deg = std::atan2(notch.inward.y(), notch.inward.x()) * 180.0 / std::numbers::pi;
    dxf.point(aama::kNotchLayer, notch.at_mm, angle_deg);
  }
  if (piece.grain_line_mm) dxf.line(aama::kGrainLayer, (*piece.grain_line_mm)[0], (*piece.grain_line_mm)[1]);
  for (const auto& line : piece.internal_lines_mm) draw_line(dxf, aama::kInternalLayer, line);
  for (const auto& line : piece.sew_lines_mm) draw_line(dxf, aama::kSewLayer, line);
}

// Lower-left and upper-right corners of what the layout must keep apart: every drawn point.
std::pair<Point2, Point2> piece_box(const PatternPiece& piece) {
  Point2 low = piece.cut_line_mm.front(), high = low;
  auto add = [&](const Point2& p) { low = low.cwiseMin(p), high = high.cwiseMax(p); };
  for (const Point2& p : piece.cut_line_mm) add(p);
  for (const auto& line : piece.internal_lines_mm)
    for (const Point2& p : line) add(p);
  for (const auto& line : piece.sew_lines_mm)
    for (const Point2& p : line) add(p);
  if (piece.grain_line_mm) add((*piece.grain_line_mm)[0]), add((*piece.grain_line_mm)[1]);
  return {low, high};
}

}  // namespace

std::string aama_dxf_text(const std::vector<PatternPiece>& pieces) {
  if (pieces.empty()) throw EngineError("DXF-AAMA: no pieces to write");
  for (const PatternPiece& piece : pieces) check_piece(piece);
  // Layer colours as pattern CAD shows them: the cut line white/black, notches red, grain green,
  // internal lines blue, sew lines magenta.
  DxfDocument dxf(DxfVersion::R12, {{aama::kBoundaryLayer, 7},
                                    {aama::kNotchLayer, 1},
                                    {aama::kGrainLayer, 3},
                                    {aama::kInternalLayer, 5},
                                    {aama::kSewLayer, 6}});
  std::set<std::string> taken;
  double cursor_x_mm = 0.0;
  for (const PatternPiece& piece : pieces) {
    const std::string name = block_name(piece.name, taken);
    dxf.begin_block(name, aama::kBoundaryLayer);
    draw_piece(dxf, piece);
    dxf.end_block();
    const auto [low, high] = piece_box(piece);
    dxf.insert(aama::kBoundaryLayer, name, Point2(cursor_x_mm - low.x(), -low.y()));
    cursor_x_mm += high.x() - low.x() + kPieceGap_mm;
  }
  // The style system text: the units, below the layout.
  dxf.text(aama::kBoundaryLayer, Point2(0.0, -3.0 * kAamaTextHeight_mm), kAamaTextHeight_mm,
           std::string(aama::kUnitsKey) + ": " + aama::kMetricUnits);
  return dxf.str();
}

void write_aama_dxf(const std::filesystem::path& path, const std::vector<PatternPiece>& pieces) {
  std::string text;
  try {
    text = aama_dxf_text(pieces);
  } catch (const EngineError& error) {
    throw EngineError(path.string() + ": " + error.what());
  }
  if (const Status status = write_file_durably(path, text); !status) throw EngineError(status.error());
}

}  // namespace lastcut
