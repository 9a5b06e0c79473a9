// Reading hide files (DXF layers or jagua-rs JSON) into a Bin; see hide_file.hpp for the formats.
#include "engine/nest/hide_file.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>

#include "engine/core/dxf_reader.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/nest/nest_json.hpp"

namespace lastcut {
namespace {

constexpr double kCurveTolerance_mm = 0.01;

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

double degrees_of(const Point2& from, const Point2& to) {
  return std::atan2(to.y() - from.y(), to.x() - from.x()) * 180.0 / std::numbers::pi;
}

// The grade q of a layer named ZONE_<q>, or nullopt for other layers.
std::optional<int> zone_grade(const std::string& layer, const std::string& source) {
  const std::string upper_prefix = "ZONE_";
  if (layer.size() < upper_prefix.size() || lower(layer.substr(0, 5)) != "zone_") return std::nullopt;
  const std::string digits = layer.substr(5);
  int grade = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), grade);
  if (digits.empty() || error != std::errc() || end != digits.data() + digits.size())
    throw EngineError(source + ": layer " + layer + " does not name a grade; zones go on ZONE_<whole number>");
  return grade;
}

Bin bin_from_dxf(const std::filesystem::path& path) {
  const std::string source = path.string();
  const DxfDrawing drawing = read_dxf_drawing(path);
  const double scale = dxf_millimetres_per_unit(path, drawing.insunits, "hide");
  Bin bin;
  int outlines = 0, open_outlines = 0;
  std::vector<Point2> backbone;  // from, to (mm)
  for (const DxfPolyline& polyline : drawing.polylines) {
    const std::string layer = lower(polyline.layer);
    const std::optional<int> grade = zone_grade(polyline.layer, source);
    if (layer == "backbone" && !polyline.closed && polyline.vertices.size() == 2) {
      backbone = {polyline.vertices[0].point * scale, polyline.vertices[1].point * scale};
      continue;
    }
    if (layer != "hide" && layer != "hole" && !grade) continue;
    if (!polyline.closed || polyline.vertices.size() < 3) {
      if (layer == "hide") {
        ++open_outlines;
        continue;
      }
      throw EngineError(source + ": an open polyline on layer " + polyline.layer +
                        "; close it in the drawing program");
    }
    Polygon2 ring;
    ring.points = flatten_dxf_polyline(polyline, kCurveTolerance_mm / scale);
    for (Point2& p : ring.points) p *= scale;
    if (layer == "hide") {
      ++outlines;
      bin.outer = std::move(ring);
    } else if (layer == "hole") {
      bin.holes.push_back(std::move(ring));
    } else {
      bin.zones.push_back({std::move(ring), *grade});
    }
  }
  for (const DxfLine& line : drawing.lines)
    if (lower(line.layer) == "backbone") backbone = {line.from * scale, line.to * scale};
  if (outlines == 0 && open_outlines > 0)
    throw EngineError(source + ": the hide outline on layer HIDE is open; close it in the drawing program");
  if (outlines == 0) throw EngineError(source + ": no hide outline (a closed polyline on layer HIDE)");
  if (outlines + open_outlines > 1)
    throw EngineError(source + ": " + std::to_string(outlines + open_outlines) +
                      " polylines on layer HIDE; a hide file holds one hide");
  if (!backbone.empty()) {
    if ((backbone[1] - backbone[0]).norm() <= 0)
      throw EngineError(source + ": the BACKBONE line has no length");
    bin.backbone_deg = degrees_of(backbone[0], backbone[1]);
    bin.backbone_point = 0.5 * (backbone[0] + backbone[1]);
  }
  return bin;
}

Bin bin_from_json_file(const std::filesystem::path& path) {
  const std::string source = path.string();
  const nlohmann::json document = read_json_file(path);
  if (!document.is_object()) throw EngineError(source + ": expected a JSON object (a hide)");
  const nlohmann::json* object = &document;
  if (document.contains("bins")) {
    if (!document["bins"].is_array() || document["bins"].size() != 1)
      throw EngineError(source + ": \"bins\" must hold exactly one hide");
    object = &document["bins"][0];
  }
  if (!object->is_object() || (!object->contains("shape") && !object->contains("outer")))
    throw EngineError(source + ": no hide outline (\"shape\" or \"outer\")");
  nlohmann::json bin_json = *object;
  if (!bin_json.contains("id")) bin_json["id"] = 0;
  Bin bin = bin_from_json(bin_json, source);
  double scale = 1.0;
  // "units" of the document, else of the bin, else mm; a value that is not text is refused (it threw
  // nlohmann's type_error past every caller: tests/fuzz/hide_json_fuzz.cpp).
  const nlohmann::json* units_json = document.contains("units") ? &document["units"]
                                     : object->contains("units") ? &(*object)["units"]
                                                                 : nullptr;
  if (units_json != nullptr && !units_json->is_string())
    throw EngineError(source + ": \"units\" must be text: mm, cm, m or in");
  const std::string units = units_json != nullptr ? units_json->get<std::string>() : std::string("mm");
  if (units == "mm") scale = 1.0;
  else if (units == "cm") scale = 10.0;
  else if (units == "m") scale = 1000.0;
  else if (units == "in") scale = 25.4;
  else throw EngineError(source + ": units \"" + units + "\" are not supported; use mm, cm, m or in");
  const auto scale_ring = [scale](Polygon2& ring) {
    for (Point2& p : ring.points) p *= scale;
  };
  scale_ring(bin.outer);
  for (Polygon2& hole : bin.holes) scale_ring(hole);
  for (QualityZone& zone : bin.zones) scale_ring(zone.shape);
  if (object->contains("name") && (*object)["name"].is_string()) bin.name = (*object)["name"].get<std::string>();
  if (object->contains("backbone_deg")) {
    const nlohmann::json& value = (*object)["backbone_deg"];
    if (!value.is_number() || !std::isfinite(value.get<double>()))
      throw EngineError(source + ": \"backbone_deg\" must be a number (degrees)");
    bin.backbone_deg = value.get<double>();
  }
  return bin;
}

}  // namespace

std::filesystem::path hide_sidecar_path(const std::filesystem::path& hide_file) {
  return hide_file.parent_path() / (hide_file.stem().string() + ".toml");
}

HideFile read_hide_file(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw EngineError("cannot read hide file " + path.string());
  const std::string extension = lower(path.extension().string());
  HideFile hide;
  if (extension == ".dxf") hide.bin = bin_from_dxf(path);
  else if (extension == ".json") hide.bin = bin_from_json_file(path);
  else throw EngineError(path.string() + ": not a hide file; expected .dxf or .json");
  make_counter_clockwise(hide.bin.outer);
  for (Polygon2& hole : hide.bin.holes) make_counter_clockwise(hole);
  for (QualityZone& zone : hide.bin.zones) make_counter_clockwise(zone.shape);
  check_hide(hide.bin, path.string());
  hide.hide_id = hide.bin.name.empty() ? path.stem().string() : hide.bin.name;
  const std::filesystem::path sidecar = hide_sidecar_path(path);
  if (std::filesystem::exists(sidecar, error)) read_hide_sidecar(sidecar, hide);
  hide.bin.id = 0;
  hide.bin.name = hide.hide_id;
  hide.bin.stock = 1;
  hide.area_m2 = signed_area(hide.bin.outer) * 1e-6;
  double holes_mm2 = 0;
  for (const Polygon2& hole : hide.bin.holes) holes_mm2 += std::abs(signed_area(hole));
  hide.usable_area_m2 = hide.area_m2 - holes_mm2 * 1e-6;
  return hide;
}

}  // namespace lastcut
