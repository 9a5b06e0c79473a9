// Reading DXF-AAMA files (aama_dxf.hpp): the DXF parsed by engine/core/dxf_reader, then the
// inserted blocks read as pieces by the layer and system-text conventions.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/dxf_reader.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/pattern/aama_conventions.hpp"
#include "engine/pattern/aama_dxf.hpp"

namespace lastcut {
namespace {

constexpr double kAamaCurveTolerance_mm = 0.05;  // bulge arcs of other CAD's cut lines, flattened

std::string upper_trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  std::string out = text.substr(first, text.find_last_not_of(" \t") - first + 1);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// "Key: value" system texts of one layer-1 TEXT list, keys upper-cased, values trimmed. A key
// written twice keeps its first value.
std::map<std::string, std::string> system_texts(const std::vector<DxfText>& texts) {
  std::map<std::string, std::string> values;
  for (const DxfText& text : texts) {
    const auto colon = text.text.find(':');
    if (text.layer != aama::kBoundaryLayer || colon == std::string::npos) continue;
    std::string value = text.text.substr(colon + 1);
    value.erase(0, value.find_first_not_of(" \t"));
    value.erase(value.find_last_not_of(" \t") + 1);
    values.emplace(upper_trimmed(text.text.substr(0, colon)), value);
  }
  return values;
}

std::string text_value(const std::map<std::string, std::string>& texts, const char* key) {
  const auto found = texts.find(upper_trimmed(key));
  return found == texts.end() ? std::string() : found->second;
}

// mm per unit of a "Units:" text; 0 for a word it does not know.
double units_text_millimetres(const std::string& word) {
  const std::string w = upper_trimmed(word);
  if (w == "METRIC" || w == "MM" || w == "MILLIMETER" || w == "MILLIMETERS" || w == "MILLIMETRE" || w == "MILLIMETRES")
    return 1.0;
  if (w == "CM" || w == "CENTIMETER" || w == "CENTIMETERS" || w == "CENTIMETRE" || w == "CENTIMETRES") return 10.0;
  if (w == "ENGLISH" || w == "IMPERIAL" || w == "INCH" || w == "INCHES" || w == "IN") return 25.4;
  return 0.0;
}

// The blocks the INSERTs of ENTITIES place, each once, in the order first placed.
std::vector<const DxfBlock*> piece_blocks(const DxfDrawing& drawing, const std::string& file_name) {
  std::vector<const DxfBlock*> blocks;
  for (const DxfInsert& insert : drawing.inserts) {
    const auto block = std::find_if(drawing.blocks.begin(), drawing.blocks.end(),
                                    [&](const DxfBlock& b) { return b.name == insert.block; });
    if (block == drawing.blocks.end())
      throw EngineError(file_name + ": an INSERT places block \"" + insert.block.substr(0, 80) +
                        "\", which the BLOCKS section does not define");
    if (std::find(blocks.begin(), blocks.end(), &*block) == blocks.end()) blocks.push_back(&*block);
  }
  return blocks;
}

// mm per drawing unit from $INSUNITS and the "Units:" texts of ENTITIES and the piece blocks.
double millimetres_per_unit(const DxfDrawing& drawing, const std::vector<const DxfBlock*>& blocks,
                            const std::string& file_name) {
  std::vector<std::string> words;
  auto collect = [&](const std::vector<DxfText>& texts) {
    const std::string word = text_value(system_texts(texts), aama::kUnitsKey);
    if (!word.empty()) words.push_back(word);
  };
  collect(drawing.texts);
  for (const DxfBlock* block : blocks) collect(block->entities.texts);
  double text_scale = 0.0;
  for (const std::string& word : words) {
    const double scale = units_text_millimetres(word);
    if (scale == 0.0)
      throw EngineError(file_name + ": unknown units \"Units: " + word.substr(0, 40) + "\" (METRIC, MM, CM, ENGLISH or INCH)");
    if (text_scale != 0.0 && scale != text_scale)
      throw EngineError(file_name + ": the \"Units:\" texts disagree (" + words.front().substr(0, 40) + ", " +
                        word.substr(0, 40) + ")");
    text_scale = scale;
  }
  const double header_scale = dxf_millimetres_per_unit(file_name, drawing.insunits, "pattern");
  if (text_scale == 0.0) return header_scale;
  if (drawing.insunits != 0 && header_scale != text_scale)
    throw EngineError(file_name + ": the units text \"Units: " + words.front().substr(0, 40) + "\" and $INSUNITS " +
                      std::to_string(drawing.insunits) + " disagree");
  return text_scale;
}

std::vector<Point2> scaled(std::vector<Point2> points, double scale) {
  for (Point2& p : points) p *= scale;
  return points;
}

// A drawn line of layer 8 or 14: polylines (a closed one repeats its first point) and LINEs.
std::vector<std::vector<Point2>> drawn_lines(const DxfEntities& entities, const char* layer, double scale) {
  std::vector<std::vector<Point2>> lines;
  for (const DxfPolyline& polyline : entities.polylines) {
    if (polyline.layer != layer || polyline.vertices.empty()) continue;
    std::vector<Point2> points = scaled(flatten_dxf_polyline(polyline, kAamaCurveTolerance_mm / scale), scale);
    if (polyline.closed) points.push_back(points.front());
    lines.push_back(std::move(points));
  }
  for (const DxfLine& line : entities.lines)
    if (line.layer == layer) lines.push_back({line.from * scale, line.to * scale});
  return lines;
}

// The inward normal (unit) of the cut-line edge nearest `point`; the cut line is counter-clockwise.
Point2 inward_normal_near(const std::vector<Point2>& cut_line, const Point2& point) {
  double best = std::numeric_limits<double>::infinity();
  Point2 normal(0.0, 1.0);
  for (size_t i = 0; i < cut_line.size(); ++i) {
    const Point2& a = cut_line[i];
    const Point2& b = cut_line[(i + 1) % cut_line.size()];
    const double distance = distance_to_segment(point, a, b);
    if (distance < best && (b - a).norm() > 0.0) best = distance, normal = Point2(a.y() - b.y(), b.x() - a.x()).normalized();
  }
  return normal;
}

double distance_to_cut_line(const std::vector<Point2>& cut_line, const Point2& point) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < cut_line.size(); ++i)
    best = std::min(best, distance_to_segment(point, cut_line[i], cut_line[(i + 1) % cut_line.size()]));
  return best;
}

// Notches: POINTs with their angle (Valentina, ASTM) or short LINEs from the cut line inward (older exports).
std::vector<PatternNotch> notches(const DxfEntities& entities, const std::vector<Point2>& cut_line, double scale) {
  std::vector<PatternNotch> out;
  for (const DxfPoint& point : entities.points) {
    if (point.layer != aama::kNotchLayer) continue;
    const Point2 at = point.at * scale;
    const double angle = point.angle_deg * std::numbers::pi / 180.0;
    out.push_back({at, point.has_angle ? Point2(std::cos(angle), std::sin(angle)) : inward_normal_near(cut_line, at)});
  }
  for (const DxfLine& line : entities.lines) {
    if (line.layer != aama::kNotchLayer) continue;
    Point2 at = line.from * scale, inner = line.to * scale;
    if (distance_to_cut_line(cut_line, inner) < distance_to_cut_line(cut_line, at)) std::swap(at, inner);
    const Point2 along = inner - at;
    out.push_back({at, along.norm() > 0.0 ? Point2(along.normalized()) : inward_normal_near(cut_line, at)});
  }
  return out;
}

int quantity(const std::string& text, const std::string& refusal_prefix) {
  if (text.empty()) return 1;
  int count = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), count);
  if (error != std::errc() || end != text.data() + text.size() || count < 1)
    throw EngineError(refusal_prefix + "quantity '" + text.substr(0, 40) + "' is not a positive count");
  return count;
}

PatternPiece read_piece(const DxfBlock& block, double scale, const std::string& style_default, const std::string& file_name) {
  const DxfEntities& entities = block.entities;
  const std::map<std::string, std::string> texts = system_texts(entities.texts);
  PatternPiece piece;
  piece.name = text_value(texts, aama::kPieceNameKey);
  if (piece.name.empty()) piece.name = block.name;
  const std::string refusal_prefix = file_name + ": piece \"" + piece.name.substr(0, 80) + "\": ";
  piece.quantity = quantity(text_value(texts, aama::kQuantityKey), refusal_prefix);
  piece.size = text_value(texts, aama::kSizeKey);
  piece.style = text_value(texts, aama::kStyleNameKey);
  if (piece.style.empty()) piece.style = style_default;
  piece.category = text_value(texts, aama::kCategoryKey);
  piece.annotation = text_value(texts, aama::kAnnotationKey);

  std::vector<const DxfPolyline*> cut_lines;
  for (const DxfPolyline& polyline : entities.polylines)
    if (polyline.layer == aama::kBoundaryLayer) cut_lines.push_back(&polyline);
  if (cut_lines.empty()) throw EngineError(refusal_prefix + "no cut line on layer 1");
  if (cut_lines.size() > 1)
    throw EngineError(refusal_prefix + std::to_string(cut_lines.size()) + " cut lines on layer 1; a piece has one");
  if (!cut_lines.front()->closed) throw EngineError(refusal_prefix + "its cut line on layer 1 is open");
  Polygon2 cut_line{scaled(flatten_dxf_polyline(*cut_lines.front(), kAamaCurveTolerance_mm / scale), scale)};
  if (cut_line.points.size() < 3) throw EngineError(refusal_prefix + "its cut line on layer 1 has fewer than 3 points");
  make_counter_clockwise(cut_line);
  piece.cut_line_mm = std::move(cut_line.points);

  piece.internal_lines_mm = drawn_lines(entities, aama::kInternalLayer, scale);
  piece.sew_lines_mm = drawn_lines(entities, aama::kSewLayer, scale);
  piece.notches = notches(entities, piece.cut_line_mm, scale);
  double longest = -1.0;
  for (const DxfLine& line : entities.lines) {
    const double length = (line.to - line.from).norm();
    if (line.layer == aama::kGrainLayer && length > longest)
      longest = length, piece.grain_line_mm = std::array<Point2, 2>{line.from * scale, line.to * scale};
  }
  return piece;
}

}  // namespace

std::vector<PatternPiece> read_aama_dxf_text(const std::string& text, const std::string& file_name) {
  const DxfDrawing drawing = read_dxf_drawing_text(text, file_name);
  if (drawing.sections == 0) throw EngineError(file_name + " is not a DXF file: it has no SECTION");
  const std::vector<const DxfBlock*> blocks = piece_blocks(drawing, file_name);
  if (blocks.empty())
    throw EngineError(file_name + ": no piece blocks (DXF-AAMA places each piece as a BLOCK with an INSERT)");
  const double scale = millimetres_per_unit(drawing, blocks, file_name);
  const std::string style_default = text_value(system_texts(drawing.texts), aama::kStyleNameKey);
  std::vector<PatternPiece> pieces;
  for (const DxfBlock* block : blocks) pieces.push_back(read_piece(*block, scale, style_default, file_name));
  return pieces;
}

std::vector<PatternPiece> read_aama_dxf(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in || !std::filesystem::is_regular_file(path)) throw EngineError("cannot read pattern file " + path.string());
  std::ostringstream content;
  content << in.rdbuf();
  return read_aama_dxf_text(content.str(), path.string());
}

}  // namespace lastcut
