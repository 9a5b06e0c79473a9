#include "engine/style/forme_drawing.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <optional>

#include "engine/core/dxf_reader.hpp"
#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

constexpr double kChainGap_mm = 0.01;        // two ends this close are joined: CAD snapping puts them on each other
constexpr double kArcTolerance_mm = 0.02;    // bulges and arcs become chords no farther than this from the curve
constexpr double kMaxArcRadius_mm = 1e5;     // larger is no arc a pattern maker draws (and would make no chords)

using DrawnFragment = std::vector<Point2>;  // one entity's points, in mm

std::string lowercase_text(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

bool starts_with_word(const std::string& text, const std::string& word) { return lowercase_text(text).starts_with(word); }

std::string trimmed_text(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

struct LineLayer {
  std::string name;
  FormeHalves halves;
};

// The line a LINE- layer holds; nothing for any other layer.
std::optional<LineLayer> line_layer(const std::string& file, const std::string& layer) {
  const std::string prefix = kFormeLinePrefix;
  if (!starts_with_word(layer, lowercase_text(prefix))) return std::nullopt;
  LineLayer found{layer.substr(prefix.size()), FormeHalves::Both};
  for (const auto& [word, halves] : {std::pair{"medial-", FormeHalves::Medial}, std::pair{"lateral-", FormeHalves::Lateral}})
    if (starts_with_word(found.name, word)) {
      found = {found.name.substr(std::string(word).size()), halves};
      break;
    }
  if (found.name.empty())
    throw EngineError(file + ": layer " + layer + " names no line: call it LINE-<name>, LINE-medial-<name> or LINE-lateral-<name>");
  const auto bad = std::find_if(found.name.begin(), found.name.end(), [](char c) {
    return !(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_');
  });
  if (bad != found.name.end())
    throw EngineError(file + ": layer \"" + layer + "\": a line's name holds letters, digits, - and _ only (an R12 layer name)");
  return found;
}

DrawnFragment arc_points(const DxfArc& arc, double mm_per_unit) {
  const double radius_mm = arc.radius * mm_per_unit;
  double sweep_deg = std::fmod(arc.end_deg - arc.start_deg, 360.0);
  if (sweep_deg <= 0) sweep_deg += 360.0;
  const double step = 2.0 * std::acos(std::max(-1.0, 1.0 - kArcTolerance_mm / radius_mm));
  const int chords = std::max(1, static_cast<int>(std::ceil(sweep_deg * std::numbers::pi / 180.0 / step)));
  DrawnFragment points;
  for (int k = 0; k <= chords; ++k) {
    const double angle = (arc.start_deg + sweep_deg * k / chords) * std::numbers::pi / 180.0;
    points.push_back(arc.centre * mm_per_unit + radius_mm * Point2(std::cos(angle), std::sin(angle)));
  }
  return points;
}

DrawnFragment polyline_points(const DxfPolyline& polyline, double mm_per_unit) {
  DxfPolyline open = polyline;
  if (!polyline.closed && !open.vertices.empty()) open.vertices.back().bulge = 0;  // no closing segment
  DrawnFragment points = flatten_dxf_polyline(open, kArcTolerance_mm / mm_per_unit);
  if (polyline.closed && !points.empty()) points.push_back(points.front());
  for (Point2& p : points) p *= mm_per_unit;
  return points;
}

// The fragments of one layer joined end to end into one line (reversing fragments as needed).
DrawnFragment chained_line(const std::string& what, std::vector<DrawnFragment> fragments) {
  const auto ends_meet = [](const Point2& a, const Point2& b) { return (a - b).norm() <= kChainGap_mm; };
  // Start at an end no other fragment meets (an open line); if every end is met, the line is closed.
  std::size_t start = 0;
  bool reverse_start = false, found = false;
  for (std::size_t i = 0; i < fragments.size() && !found; ++i)
    for (const bool back : {false, true}) {
      const Point2& end = back ? fragments[i].back() : fragments[i].front();
      int met = 0;
      for (std::size_t j = 0; j < fragments.size(); ++j)
        if (j != i) met += ends_meet(end, fragments[j].front()) + ends_meet(end, fragments[j].back());
      if (met == 0 && !found) start = i, reverse_start = back, found = true;
    }
  DrawnFragment line = fragments[start];
  if (reverse_start) std::reverse(line.begin(), line.end());
  std::vector<char> used(fragments.size(), 0);
  used[start] = 1;
  for (std::size_t joined = 1; joined < fragments.size(); ++joined) {
    std::optional<std::size_t> next;
    bool flip = false;
    for (std::size_t j = 0; j < fragments.size(); ++j) {
      if (used[j]) continue;
      for (const bool back : {false, true}) {
        if (!ends_meet(line.back(), back ? fragments[j].back() : fragments[j].front())) continue;
        if (next && *next != j)
          throw EngineError(what + " branches at " + forme_point_text(line.back()) + ": a line is one stroke, end to end");
        next = j, flip = back;
      }
    }
    if (!next)
      throw EngineError(what + " is in " + std::to_string(fragments.size() - joined + 1) + " parts that do not join: one ends at " +
                        forme_point_text(line.back()) + "; join them end to end");
    DrawnFragment piece = fragments[*next];
    if (flip) std::reverse(piece.begin(), piece.end());
    line.insert(line.end(), piece.begin() + 1, piece.end());
    used[*next] = 1;
  }
  if (line.size() > 2 && ends_meet(line.front(), line.back())) line.back() = line.front();
  DrawnFragment distinct;  // without the repeated points of zero-length pieces
  for (const Point2& p : line)
    if (distinct.empty() || (p - distinct.back()).norm() > 0) distinct.push_back(p);
  line = std::move(distinct);
  if (line.size() < 2) throw EngineError(what + " has no length");
  return line;
}

}  // namespace

std::string forme_point_text(const Point2& at_mm) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.1f, %.1f)", at_mm.x(), at_mm.y());
  return text;
}

FormeDrawing read_forme_drawing(const std::filesystem::path& dxf) {
  const DxfDrawing drawing = read_dxf_drawing(dxf);
  const double mm_per_unit = dxf_millimetres_per_unit(dxf, drawing.insunits, "forme");
  FormeDrawing result;
  result.source = dxf.string();
  const std::string& file = result.source;

  // Fragments per layer, layers in the order they first appear.
  std::vector<std::string> order;
  std::map<std::string, std::vector<DrawnFragment>> fragments;
  const auto add = [&](const std::string& layer, DrawnFragment points) {
    if (!line_layer(file, layer)) return;
    if (!fragments.contains(layer)) order.push_back(layer);
    if (points.size() >= 2) fragments[layer].push_back(std::move(points));
  };
  for (const DxfPolyline& polyline : drawing.polylines) add(polyline.layer, polyline_points(polyline, mm_per_unit));
  for (const DxfLine& line : drawing.lines) add(line.layer, {line.from * mm_per_unit, line.to * mm_per_unit});
  for (const DxfArc& arc : drawing.arcs) {
    if (!line_layer(file, arc.layer)) continue;
    if (!(arc.radius * mm_per_unit > kChainGap_mm && arc.radius * mm_per_unit < kMaxArcRadius_mm))
      throw EngineError(file + ": line on layer " + arc.layer + ": an ARC of radius " + std::to_string(arc.radius) + " is not drawable");
    add(arc.layer, arc_points(arc, mm_per_unit));
  }
  std::vector<DxfOtherEntity> unread = drawing.others;  // a block's lines or a point on a line layer are no line either
  for (const DxfInsert& insert : drawing.inserts) unread.push_back({"INSERT", insert.layer});
  for (const DxfPoint& point : drawing.points) unread.push_back({"POINT", point.layer});
  for (const DxfOtherEntity& other : unread)
    if (line_layer(file, other.layer))
      throw EngineError(file + ": line on layer " + other.layer + " has a " + other.type +
                        ", which lastcut does not read: draw it with lines, polylines or arcs (explode or convert it)");

  std::map<std::string, std::string> layer_of_name;  // to refuse one name on a both-halves and a one-half layer
  for (const std::string& layer : order) {
    const LineLayer parsed = *line_layer(file, layer);
    const std::string what = file + ": line " + parsed.name + " (layer " + layer + ")";
    if (fragments[layer].empty()) throw EngineError(what + " has no length");
    if (const auto other = layer_of_name.find(parsed.name); other != layer_of_name.end()) {
      const FormeHalves other_halves = line_layer(file, other->second)->halves;
      if (parsed.halves == FormeHalves::Both || other_halves == FormeHalves::Both || other_halves == parsed.halves)
        throw EngineError(file + ": line " + parsed.name + " is drawn on layers " + other->second + " and " + layer +
                          ": draw it once for both halves (LINE-name) or once per half (LINE-medial-, LINE-lateral-)");
    }
    layer_of_name.emplace(parsed.name, layer);
    result.lines.push_back({parsed.name, layer, parsed.halves, chained_line(what, fragments[layer])});
  }

  for (const DxfText& text : drawing.texts) {
    if (lowercase_text(text.layer) != lowercase_text(kFormePiecesLayer)) continue;
    FormePieceText piece{trimmed_text(text.text), FormeHalves::Lateral, text.at * mm_per_unit};
    if (piece.name.empty()) throw EngineError(file + ": an empty text on layer PIECES at " + forme_point_text(piece.at_mm));
    if (starts_with_word(piece.name, "medial ")) piece.half = FormeHalves::Medial;
    for (const FormePieceText& other : result.pieces)
      if (other.name == piece.name)
        throw EngineError(file + ": piece " + piece.name + " is named twice on layer PIECES, at " + forme_point_text(other.at_mm) +
                          " and " + forme_point_text(piece.at_mm) + ": one text per piece");
    result.pieces.push_back(piece);
  }
  if (result.pieces.empty())
    throw EngineError(file + ": no piece text: write each piece's name as a TEXT on layer PIECES, inside the piece");
  return result;
}

}  // namespace lastcut
