#include "engine/core/dxf_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <utility>

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

std::vector<Group> read_groups(std::istream& in, const std::string& name) {
  std::vector<Group> groups;
  std::string code_line, value_line;
  int line = 0;
  while (std::getline(in, code_line)) {
    ++line;
    const std::string code_text = trim(code_line);
    if (code_text.empty() && in.peek() == std::istream::traits_type::eof()) break;
    int code = 0;
    const auto [end, error] = std::from_chars(code_text.data(), code_text.data() + code_text.size(), code);
    if (error != std::errc() || end != code_text.data() + code_text.size())
      throw EngineError(name + " is not a DXF file: line " + std::to_string(line) + " is not a group code");
    if (!std::getline(in, value_line))
      throw EngineError(name + " is not a DXF file: it ends in the middle of a group at line " + std::to_string(line));
    ++line;
    groups.push_back({code, trim(value_line)});
  }
  return groups;
}

double number(const std::string& name, const std::string& text) {
  double value = 0.0;
  const char* begin = text.data() + (text.starts_with('+') ? 1 : 0);
  const auto [end, error] = std::from_chars(begin, text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw EngineError(name + ": '" + text.substr(0, 40) + "' is not a number");
  return value;
}

// An integer group value (flags, $INSUNITS). Converting a double outside int's range is undefined
// behaviour (the fuzzer's 70 / 3333...331, tests/fuzz/hide_dxf_fuzz.cpp), so such a value is refused.
int integer(const std::string& name, const std::string& text) {
  const double value = number(name, text);
  if (!(value >= std::numeric_limits<int>::min() && value <= std::numeric_limits<int>::max()))
    throw EngineError(name + ": '" + text.substr(0, 40) + "' is not a DXF integer (out of range)");
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

// The groups of one entity (from its code 0 to the next), gathered.
struct EntityFields {
  std::string layer, text, name;
  std::string text_chunks;  // MTEXT: the parts of a long text before its last (group 3)
  int flags = 0;
  bool has_angle = false;
  double angle_deg = 0.0;   // 50: a POINT's direction, an ARC's start
  double end_deg = 0.0;     // 51: an ARC's end
  double radius = 0.0;      // 40: an ARC's
  std::vector<DxfVertex> vertices;  // every 10/20 (and 42) in order
  Point2 second = Point2::Zero();   // 11/21
};

EntityFields entity_fields(const std::vector<Group>& groups, size_t first, size_t end, const std::string& name) {
  EntityFields f;
  for (size_t k = first; k < end; ++k) {
    const Group& field = groups[k];
    if (field.code == 8) f.layer = field.value;
    if (field.code == 1) f.text = field.value;
    if (field.code == 3) f.text_chunks += field.value;
    if (field.code == 2) f.name = field.value;
    if (field.code == 70) f.flags = integer(name, field.value);
    if (field.code == 50) f.has_angle = true, f.angle_deg = number(name, field.value);
    if (field.code == 51) f.end_deg = number(name, field.value);
    if (field.code == 40) f.radius = number(name, field.value);
    if (field.code == 10) f.vertices.push_back({Point2(number(name, field.value), 0.0), 0.0});
    if (field.code == 20 && !f.vertices.empty()) f.vertices.back().point.y() = number(name, field.value);
    if (field.code == 42 && !f.vertices.empty()) f.vertices.back().bulge = number(name, field.value);
    if (field.code == 11) f.second.x() = number(name, field.value);
    if (field.code == 21) f.second.y() = number(name, field.value);
  }
  return f;
}

Point2 first_point(const EntityFields& f) { return f.vertices.empty() ? Point2::Zero() : f.vertices.front().point; }

// Files the entity of `type` into `into`; `in_polyline` is true between POLYLINE and SEQEND.
void add_entity(DxfEntities& into, const std::string& type, EntityFields f, bool& in_polyline, const std::string& name) {
  if (type == "LWPOLYLINE") {
    into.polylines.push_back({f.layer, std::move(f.vertices), (f.flags & 1) != 0});
  } else if (type == "POLYLINE") {
    into.polylines.push_back({f.layer, {}, (f.flags & 1) != 0});
    in_polyline = true;
  } else if (type == "VERTEX" && in_polyline) {
    if (f.vertices.size() != 1) throw EngineError(name + ": a VERTEX without one coordinate pair");
    into.polylines.back().vertices.push_back(f.vertices.front());
  } else if (type == "SEQEND") {
    in_polyline = false;
  } else if (type == "LINE") {
    if (f.vertices.size() == 1) into.lines.push_back({f.layer, f.vertices.front().point, f.second});
  } else if (type == "TEXT" || type == "MTEXT") {
    into.texts.push_back({f.layer, type == "MTEXT" ? f.text_chunks + f.text : f.text, first_point(f)});
  } else if (type == "ARC") {
    if (f.vertices.size() == 1) into.arcs.push_back({f.layer, f.vertices.front().point, f.radius, f.angle_deg, f.end_deg});
  } else if (type == "POINT") {
    into.points.push_back({f.layer, first_point(f), f.has_angle, f.angle_deg});
  } else if (type == "INSERT") {
    into.inserts.push_back({f.layer, f.name, first_point(f)});
  } else if (type != "VERTEX") {
    into.others.push_back({type, f.layer});
  }
}

void drop_repeated_first_points(DxfEntities& entities) {
  for (auto& polyline : entities.polylines) {
    auto& v = polyline.vertices;
    if (v.size() >= 2 && v.front().point == v.back().point) polyline.closed = true, v.pop_back();
  }
}

DxfDrawing parse_drawing(const std::vector<Group>& groups, const std::string& name) {
  if (groups.empty()) throw EngineError(name + ": the file is empty");
  DxfDrawing drawing;
  DxfEntities* into = nullptr;  // ENTITIES, or the block being read; null elsewhere
  bool in_polyline = false;     // between POLYLINE and SEQEND
  std::string section;
  for (size_t g = 0; g < groups.size(); ++g) {
    const Group& group = groups[g];
    if (group.code == 0 && group.value == "SECTION" && g + 1 < groups.size() && groups[g + 1].code == 2) {
      section = groups[g + 1].value;
      ++drawing.sections;
      into = section == "ENTITIES" ? &drawing : nullptr;
      in_polyline = false;
      continue;
    }
    if (group.code == 0 && group.value == "ENDSEC") {
      section.clear();
      continue;
    }
    if (section == "HEADER" && group.code == 9 && group.value == "$INSUNITS" && g + 1 < groups.size())
      drawing.insunits = integer(name, groups[g + 1].value);
    if (section == "TABLES" && group.code == 0 && group.value == "LAYER")
      for (size_t k = g + 1; k < groups.size() && groups[k].code != 0; ++k)
        if (groups[k].code == 2) drawing.layers.push_back(groups[k].value);
    if ((section != "ENTITIES" && section != "BLOCKS") || group.code != 0) continue;
    // An entity: its groups run to the next code 0.
    size_t end = g + 1;
    while (end < groups.size() && groups[end].code != 0) ++end;
    EntityFields fields = entity_fields(groups, g + 1, end, name);
    if (group.value == "ENDSEC") {
      section.clear();
      into = nullptr;
    } else if (section == "BLOCKS" && group.value == "BLOCK") {
      drawing.blocks.push_back({fields.name, first_point(fields), {}});
      into = &drawing.blocks.back().entities;
      in_polyline = false;
    } else if (section == "BLOCKS" && group.value == "ENDBLK") {
      into = nullptr;
      in_polyline = false;
    } else if (into != nullptr) {
      // A VERTEX with no POLYLINE before it in this block (a damaged file) is ignored.
      in_polyline = in_polyline && !into->polylines.empty();
      add_entity(*into, group.value, std::move(fields), in_polyline, name);
    }
    g = end - 1;
  }
  drop_repeated_first_points(drawing);
  for (DxfBlock& block : drawing.blocks) drop_repeated_first_points(block.entities);
  return drawing;
}

}  // namespace

DxfDrawing read_dxf_drawing(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw EngineError("cannot read " + path.string());
  return parse_drawing(read_groups(in, path.string()), path.string());
}

DxfDrawing read_dxf_drawing_text(const std::string& text, const std::string& file_name) {
  std::istringstream in(text);
  return parse_drawing(read_groups(in, file_name), file_name);
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
  const size_t segments = polyline.closed ? v.size() : (v.empty() ? 0 : v.size() - 1);
  for (size_t i = 0; i < segments; ++i) append_segment(points, v[i], v[(i + 1) % v.size()].point, tolerance);
  if (!polyline.closed && !v.empty()) points.push_back(v.back().point);
  return points;
}

}  // namespace lastcut
