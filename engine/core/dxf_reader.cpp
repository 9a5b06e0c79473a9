#include "engine/core/dxf_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

struct Group {
  int code = 0;
  std::string value;
};

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

std::vector<Group> read_groups(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw EngineError("cannot read " + path.string());
  std::vector<Group> groups;
  std::string code_line, value_line;
  int line = 0;
  while (std::getline(in, code_line)) {
    ++line;
    const std::string code_text = trim(code_line);
    if (code_text.empty() && in.peek() == std::ifstream::traits_type::eof()) break;
    int code = 0;
    const auto [end, error] = std::from_chars(code_text.data(), code_text.data() + code_text.size(), code);
    if (error != std::errc() || end != code_text.data() + code_text.size())
      throw EngineError(path.string() + " is not a DXF file: line " + std::to_string(line) + " is not a group code");
    if (!std::getline(in, value_line))
      throw EngineError(path.string() + " is not a DXF file: it ends in the middle of a group at line " +
                        std::to_string(line));
    ++line;
    groups.push_back({code, trim(value_line)});
  }
  return groups;
}

double number(const std::filesystem::path& path, const std::string& text) {
  double value = 0.0;
  const char* begin = text.data() + (text.starts_with('+') ? 1 : 0);
  const auto [end, error] = std::from_chars(begin, text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw EngineError(path.string() + ": '" + text + "' is not a number");
  return value;
}

// An integer group value (flags, $INSUNITS). Converting a double outside int's range is undefined
// behaviour (the fuzzer's 70 / 3333...331, tests/fuzz/hide_dxf_fuzz.cpp), so such a value is refused.
int integer(const std::filesystem::path& path, const std::string& text) {
  const double value = number(path, text);
  if (!(value >= std::numeric_limits<int>::min() && value <= std::numeric_limits<int>::max()))
    throw EngineError(path.string() + ": '" + text.substr(0, 40) + "' is not a DXF integer (out of range)");
  return static_cast<int>(value);
}

// Appends the segment from a to b, an arc when bulge != 0, without b itself.
void append_segment(std::vector<Point2>& points, const DxfVertex& a, const Point2& b, double tolerance) {
  points.push_back(a.point);
  const double chord = (b - a.point).norm();
  if (a.bulge == 0.0 || chord == 0.0) return;
  const double sweep = 4.0 * std::atan(a.bulge);  // signed, counter-clockwise positive
  const double radius = chord / (2.0 * std::abs(std::sin(sweep / 2.0)));
  const double step = 2.0 * std::acos(std::max(-1.0, 1.0 - tolerance / radius));
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / std::max(step, 1e-6))));
  // Centre: on the chord's perpendicular bisector, at distance (chord/2) / tan(sweep/2).
  const Point2 mid = 0.5 * (a.point + b);
  const Point2 along = (b - a.point) / chord;
  const Point2 left(-along.y(), along.x());
  const Point2 centre = mid + left * (0.5 * chord / std::tan(sweep / 2.0));
  const Point2 from = a.point - centre;
  for (int k = 1; k < pieces; ++k) {
    const double angle = sweep * k / pieces;
    points.emplace_back(centre.x() + std::cos(angle) * from.x() - std::sin(angle) * from.y(),
                        centre.y() + std::sin(angle) * from.x() + std::cos(angle) * from.y());
  }
}

}  // namespace

DxfDrawing read_dxf_drawing(const std::filesystem::path& path) {
  const std::vector<Group> groups = read_groups(path);
  if (groups.empty()) throw EngineError(path.string() + ": the file is empty");
  DxfDrawing drawing;
  bool in_polyline = false;  // between POLYLINE and SEQEND
  std::string section;
  for (size_t g = 0; g < groups.size(); ++g) {
    const Group& group = groups[g];
    if (group.code == 0 && group.value == "SECTION" && g + 1 < groups.size() && groups[g + 1].code == 2) {
      section = groups[g + 1].value;
      continue;
    }
    if (group.code == 0 && group.value == "ENDSEC") {
      section.clear();
      continue;
    }
    if (section == "HEADER" && group.code == 9 && group.value == "$INSUNITS" && g + 1 < groups.size())
      drawing.insunits = integer(path, groups[g + 1].value);
    if (section == "TABLES" && group.code == 0 && group.value == "LAYER")
      for (size_t k = g + 1; k < groups.size() && groups[k].code != 0; ++k)
        if (groups[k].code == 2) drawing.layers.push_back(groups[k].value);
    if (section != "ENTITIES" || group.code != 0) continue;
    // An entity: its groups run to the next code 0.
    size_t end = g + 1;
    while (end < groups.size() && groups[end].code != 0) ++end;
    std::string layer, text, text_chunks;
    int flags = 0;
    std::string radius = "0", start_deg = "0", end_deg = "0";  // an ARC's, read as numbers for ARCs only
    std::vector<DxfVertex> vertices;
    Point2 line_end = Point2::Zero();
    for (size_t k = g + 1; k < end; ++k) {
      const Group& field = groups[k];
      if (field.code == 8) layer = field.value;
      if (field.code == 1) text = field.value;
      if (field.code == 3) text_chunks += field.value;  // MTEXT: the parts of a long text before its last (group 1)
      if (field.code == 40) radius = field.value;
      if (field.code == 50) start_deg = field.value;
      if (field.code == 51) end_deg = field.value;
      if (field.code == 70) flags = integer(path, field.value);
      if (field.code == 10) vertices.push_back({Point2(number(path, field.value), 0.0), 0.0});
      if (field.code == 20 && !vertices.empty()) vertices.back().point.y() = number(path, field.value);
      if (field.code == 42 && !vertices.empty()) vertices.back().bulge = number(path, field.value);
      if (field.code == 11) line_end.x() = number(path, field.value);
      if (field.code == 21) line_end.y() = number(path, field.value);
    }
    if (group.value == "LWPOLYLINE") {
      drawing.polylines.push_back({layer, std::move(vertices), (flags & 1) != 0});
    } else if (group.value == "POLYLINE") {
      drawing.polylines.push_back({layer, {}, (flags & 1) != 0});
      in_polyline = true;
    } else if (group.value == "VERTEX" && in_polyline) {
      if (vertices.size() != 1) throw EngineError(path.string() + ": a VERTEX without one coordinate pair");
      drawing.polylines.back().vertices.push_back(vertices.front());
    } else if (group.value == "SEQEND") {
      in_polyline = false;
    } else if (group.value == "LINE") {
      if (vertices.size() == 1) drawing.lines.push_back({layer, vertices.front().point, line_end});
    } else if (group.value == "TEXT" || group.value == "MTEXT") {
      const Point2 at = vertices.empty() ? Point2::Zero() : vertices.front().point;
      drawing.texts.push_back({layer, group.value == "MTEXT" ? text_chunks + text : text, at});
    } else if (group.value == "ARC") {
      if (vertices.size() == 1) drawing.arcs.push_back(
            {layer, vertices.front().point, number(path, radius), number(path, start_deg), number(path, end_deg)});
    } else if (group.value != "VERTEX") {
      drawing.others.push_back({group.value, layer});
    }
    g = end - 1;
  }
  for (auto& polyline : drawing.polylines) {
    auto& v = polyline.vertices;
    if (v.size() >= 2 && v.front().point == v.back().point) polyline.closed = true, v.pop_back();
  }
  return drawing;
}

double dxf_millimetres_per_unit(const std::filesystem::path& path, int insunits, const std::string& what) {
  switch (insunits) {
    case 0: return 1.0;  // unitless: pattern CAD and digitizers write mm
    case 1: return 25.4;
    case 4: return 1.0;
    case 5: return 10.0;
    case 6: return 1000.0;
    default:
      throw EngineError(path.string() + ": drawing units $INSUNITS " + std::to_string(insunits) +
                        " are not supported; save the " + what + " in mm, cm, m or inches");
  }
}

std::vector<Point2> flatten_dxf_polyline(const DxfPolyline& polyline, double tolerance) {
  std::vector<Point2> points;
  const auto& v = polyline.vertices;
  for (size_t i = 0; i < v.size(); ++i) append_segment(points, v[i], v[(i + 1) % v.size()].point, tolerance);
  return points;
}

}  // namespace lastcut
