#include "engine/mold/mold_dxf.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/dxf_document.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/core/polygon_centroid.hpp"

namespace lastcut {

namespace {

constexpr double kTextHeight_mm = 2.5;

// One entity of the ENTITIES section: its type and its group pairs in file order.
struct Entity {
  std::string type;
  std::vector<std::pair<int, std::string>> pairs;
  std::string layer() const {
    for (const auto& [code, value] : pairs)
      if (code == 8) return value;
    return {};
  }
};

std::string trim(std::string s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

std::vector<Entity> read_entities(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw EngineError("cannot read mold file " + path.string());
  std::vector<Entity> entities;
  bool in_entities = false;
  std::string code_line, value_line;
  int line_number = 0;
  bool expect_section_name = false;
  while (std::getline(in, code_line)) {
    ++line_number;
    if (!std::getline(in, value_line))
      throw EngineError(path.string() + " is not a DXF file: it ends in the middle of a group at line " +
                        std::to_string(line_number));
    ++line_number;
    const std::string code_text = trim(code_line);
    int code = 0;
    const auto [end, error] = std::from_chars(code_text.data(), code_text.data() + code_text.size(), code);
    if (error != std::errc() || end != code_text.data() + code_text.size())
      throw EngineError(path.string() + " is not a DXF file: line " + std::to_string(line_number - 1) +
                        " is not a group code");
    std::string value = trim(value_line);
    if (code == 0) {
      expect_section_name = value == "SECTION";
      if (value == "ENDSEC" || value == "EOF") in_entities = false;
      if (in_entities) entities.push_back({value, {}});
      continue;
    }
    if (expect_section_name && code == 2) {
      in_entities = value == "ENTITIES";
      expect_section_name = false;
      continue;
    }
    if (in_entities && !entities.empty()) entities.back().pairs.emplace_back(code, std::move(value));
  }
  return entities;
}

double to_number(const std::filesystem::path& path, const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw EngineError(path.string() + ": '" + text + "' is not a coordinate");
  return value;
}

// Points of the first coordinate group (10/20) of each repetition in an entity.
std::vector<Point2> points_of(const std::filesystem::path& path, const Entity& entity) {
  std::vector<Point2> points;
  for (const auto& [code, value] : entity.pairs) {
    if (code == 10) points.emplace_back(to_number(path, value), 0.0);
    if (code == 20 && !points.empty()) points.back().y() = to_number(path, value);
  }
  return points;
}

int flags_of(const Entity& entity) {
  for (const auto& [code, value] : entity.pairs)
    if (code == 70) return std::atoi(value.c_str());
  return 0;
}

std::string text_of(const Entity& entity) {
  for (const auto& [code, value] : entity.pairs)
    if (code == 1) return value;
  return {};
}

}  // namespace

void write_mold_dxf(const std::filesystem::path& path, const Mold& mold) {
  DxfDocument dxf(DxfVersion::R12, {{"CUT", 7}, {"MARK", 1}, {"LABEL", 3}, {"NET", 5}});  // white, red, green, blue
  dxf.polyline("CUT", mold.outline.points, true);
  if (!mold.net.points.empty()) dxf.polyline("NET", mold.net.points, true);
  for (const auto& mark : mold.marks) {
    const Point2 inner = notch_inner_end(mark);
    dxf.line("MARK", mark.position_mm, inner);
    dxf.text("MARK", inner, kTextHeight_mm, mark.name);
  }
  if (!mold.name.empty() && !mold.outline.points.empty())
    dxf.text("LABEL", area_centroid(mold.outline), kTextHeight_mm, mold.name);

  std::ofstream out(path, std::ios::binary);
  const std::string text = dxf.str();
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out) throw EngineError("cannot write mold file " + path.string());
}

Mold read_mold_dxf(const std::filesystem::path& path) {
  const std::vector<Entity> entities = read_entities(path);
  Mold mold;
  int outlines = 0, net_lines = 0;
  struct Notch {
    Point2 from, to;
  };
  std::vector<Notch> notches;
  std::vector<std::pair<Point2, std::string>> mark_texts;
  for (size_t e = 0; e < entities.size(); ++e) {
    const Entity& entity = entities[e];
    const std::string layer = entity.layer();
    const bool is_polyline = entity.type == "POLYLINE" || entity.type == "LWPOLYLINE";
    if (is_polyline && (layer == "CUT" || layer == "NET")) {
      if (!(flags_of(entity) & 1))
        throw EngineError(path.string() + ": the " + (layer == "CUT" ? "outline" : "net line") + " on layer " + layer +
                          " is not closed");
      if (layer == "CUT") ++outlines;
      if (layer == "NET") ++net_lines;
      std::vector<Point2>& points = layer == "CUT" ? mold.outline.points : mold.net.points;
      if (entity.type == "LWPOLYLINE") {
        points = points_of(path, entity);
      } else {
        points.clear();
        for (size_t v = e + 1; v < entities.size() && entities[v].type == "VERTEX"; ++v) {
          const auto vertex = points_of(path, entities[v]);
          if (vertex.size() != 1) throw EngineError(path.string() + ": a VERTEX without one coordinate pair");
          points.push_back(vertex.front());
        }
      }
    } else if (layer == "MARK" && entity.type == "LINE") {
      Notch notch{points_of(path, entity).empty() ? Point2::Zero() : points_of(path, entity).front(), Point2::Zero()};
      bool has_end = false;
      for (const auto& [code, value] : entity.pairs) {
        if (code == 11) notch.to.x() = to_number(path, value), has_end = true;
        if (code == 21) notch.to.y() = to_number(path, value);
      }
      if (!has_end) throw EngineError(path.string() + ": a notch LINE on layer MARK has no end point");
      notches.push_back(notch);
    } else if (entity.type == "TEXT" && !points_of(path, entity).empty()) {
      if (layer == "MARK") mark_texts.emplace_back(points_of(path, entity).front(), text_of(entity));
      if (layer == "LABEL") mold.name = text_of(entity);
    }
  }
  if (outlines == 0) throw EngineError(path.string() + ": no closed outline on layer CUT");
  if (outlines > 1)
    throw EngineError(path.string() + ": " + std::to_string(outlines) + " outlines on layer CUT; one mold per file");
  if (mold.outline.points.size() < 3) throw EngineError(path.string() + ": the outline on layer CUT has fewer than 3 points");
  make_counter_clockwise(mold.outline);
  if (net_lines > 1)
    throw EngineError(path.string() + ": " + std::to_string(net_lines) + " net lines on layer NET; one mold per file");
  if (net_lines == 1 && mold.net.points.size() < 3)
    throw EngineError(path.string() + ": the net line on layer NET has fewer than 3 points");
  make_counter_clockwise(mold.net);
  for (const auto& notch : notches) {
    MoldMark mark;
    mark.position_mm = notch.from;
    const Point2 direction = notch.to - notch.from;
    mark.inward_direction = direction.norm() > 0.0 ? Point2(direction.normalized()) : Point2::Zero();
    // The name is the TEXT written at the notch's inner end.
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [at, name] : mark_texts) {
      const double distance = (at - notch.to).norm();
      if (distance < best && distance < 1e-3) best = distance, mark.name = name;
    }
    mold.marks.push_back(std::move(mark));
  }
  return mold;
}

}  // namespace lastcut
