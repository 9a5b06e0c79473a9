#include "engine/nest/nest_json.hpp"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& where, const std::string& what) { throw EngineError(where + ": " + what); }

double number(const json& j, const std::string& where) {
  if (!j.is_number()) fail(where, "expected a number, found " + std::string(j.type_name()));
  const double value = j.get<double>();
  if (!std::isfinite(value)) fail(where, "number is not finite");
  return value;
}

int integer(const json& j, const std::string& where) {
  if (!j.is_number_integer()) fail(where, "expected a whole number, found " + std::string(j.type_name()));
  return j.get<int>();
}

const json& field(const json& object, const char* key, const std::string& where) {
  if (!object.is_object()) fail(where, "expected an object");
  auto it = object.find(key);
  if (it == object.end()) fail(where, std::string("missing \"") + key + "\"");
  return *it;
}

Point2 point(const json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 2) fail(where, "a point must be [x, y]");
  return {number(j[0], where), number(j[1], where)};
}

// A ring of points [[x,y]..]; the repeated closing point is dropped.
Polygon2 ring(const json& j, const std::string& where) {
  if (!j.is_array()) fail(where, "a polygon must be a list of [x, y] points");
  Polygon2 polygon;
  for (const json& p : j) polygon.points.push_back(point(p, where));
  if (polygon.points.size() > 1 && polygon.points.front() == polygon.points.back()) polygon.points.pop_back();
  if (polygon.points.size() < 3)
    fail(where, "polygon has " + std::to_string(polygon.points.size()) + " points, at least 3 are needed");
  if (std::abs(signed_area(polygon)) <= 0.0) fail(where, "polygon has zero area");
  return polygon;
}

struct RingsWithHoles {
  Polygon2 outer;
  std::vector<Polygon2> holes;
};

RingsWithHoles shape(const json& j, const std::string& where) {
  if (j.is_array()) return {ring(j, where), {}};
  const std::string type = field(j, "type", where).is_string() ? j["type"].get<std::string>() : "";
  const json& data = field(j, "data", where);
  if (type == "simple_polygon") return {ring(data, where), {}};
  if (type == "polygon") {
    RingsWithHoles result{ring(field(data, "outer", where), where + " outer"), {}};
    if (data.contains("inner")) {
      if (!data["inner"].is_array()) fail(where, "\"inner\" must be a list of polygons");
      for (size_t h = 0; h < data["inner"].size(); ++h)
        result.holes.push_back(ring(data["inner"][h], where + " hole " + std::to_string(h)));
    }
    return result;
  }
  fail(where, "unknown shape type \"" + type + "\" (expected simple_polygon or polygon)");
}

json ring_json(const Polygon2& polygon) {
  json points = json::array();
  for (const Point2& p : polygon.points) points.push_back({p.x(), p.y()});
  return points;
}

ItemMark mark(const json& j, const std::string& where) {
  ItemMark m;
  if (j.contains("name")) {
    if (!j["name"].is_string()) fail(where, "mark name must be text");
    m.name = j["name"].get<std::string>();
  }
  m.from_mm = point(field(j, "from", where), where + " from");
  m.to_mm = point(field(j, "to", where), where + " to");
  return m;
}

// "drawn_lines": [[[x, y], ...], ...]; each line needs two points to be drawn at all.
std::vector<std::vector<Point2>> drawn_lines(const json& j, const std::string& where) {
  if (!j.is_array()) fail(where, "\"drawn_lines\" must be a list of lines");
  std::vector<std::vector<Point2>> lines;
  for (const json& line : j) {
    const std::string at = where + " drawn line " + std::to_string(lines.size());
    if (!line.is_array()) fail(at, "a drawn line must be a list of [x, y] points");
    if (line.size() < 2) fail(at, "has " + std::to_string(line.size()) + " points, at least 2 are needed");
    lines.emplace_back();
    for (const json& p : line) lines.back().push_back(point(p, at));
  }
  return lines;
}

NestItem item(const json& j, const std::string& source) {
  const std::string where0 = source + " item";
  NestItem it;
  it.id = integer(field(j, "id", where0), where0 + " id");
  const std::string where = source + " item " + std::to_string(it.id);
  it.shape = shape(field(j, "shape", where), where + " shape").outer;
  make_counter_clockwise(it.shape);
  if (j.contains("demand")) it.demand = integer(j["demand"], where + " demand");
  if (it.demand < 0) fail(where, "demand is negative");
  for (const char* key : {"allowed_orientations", "allowed_rotations_deg"}) {
    if (!j.contains(key)) continue;
    if (!j[key].is_array()) fail(where, std::string("\"") + key + "\" must be a list of angles");
    for (const json& a : j[key]) it.allowed_rotations_deg.push_back(number(a, where + " rotation"));
    if (it.allowed_rotations_deg.empty()) fail(where, std::string("\"") + key + "\" is empty: no rotation allowed at all");
  }
  if (j.contains("allow_mirror")) {
    if (!j["allow_mirror"].is_boolean()) fail(where, "\"allow_mirror\" must be true or false");
    it.allow_mirror = j["allow_mirror"].get<bool>();
  }
  if (j.contains("grain_deg") && !j["grain_deg"].is_null()) it.grain_deg = number(j["grain_deg"], where + " grain_deg");
  if (j.contains("grain_tolerance_deg")) it.grain_tolerance_deg = number(j["grain_tolerance_deg"], where + " grain_tolerance_deg");
  if (it.grain_tolerance_deg < 0) fail(where, "grain tolerance is negative");
  if (j.contains("min_quality") && !j["min_quality"].is_null()) it.min_quality = integer(j["min_quality"], where + " min_quality");
  if (j.contains("label")) {
    if (!j["label"].is_string()) fail(where, "\"label\" must be text");
    it.label = j["label"].get<std::string>();
  }
  if (j.contains("marks")) {
    if (!j["marks"].is_array()) fail(where, "\"marks\" must be a list");
    for (const json& m : j["marks"]) it.marks.push_back(mark(m, where + " mark"));
  }
  if (j.contains("drawn_lines")) it.drawn_lines_mm = drawn_lines(j["drawn_lines"], where);
  if (j.contains("quality_regions")) {
    if (!j["quality_regions"].is_array()) fail(where, "\"quality_regions\" must be a list");
    for (const json& r : j["quality_regions"]) {
      QualityRegion region;
      region.min_quality = integer(field(r, "min_quality", where + " quality region"), where + " quality region min_quality");
      region.shape = shape(field(r, "shape", where + " quality region"), where + " quality region shape").outer;
      make_counter_clockwise(region.shape);
      it.quality_regions.push_back(std::move(region));
    }
  }
  if (j.contains("pair_group")) {
    if (!j["pair_group"].is_string()) fail(where, "\"pair_group\" must be text");
    it.pair_group = j["pair_group"].get<std::string>();
  }
  if (j.contains("priority")) it.priority = integer(j["priority"], where + " priority");
  if (j.contains("mirror_key")) {
    if (!j["mirror_key"].is_string()) fail(where, "\"mirror_key\" must be text");
    it.mirror_key = j["mirror_key"].get<std::string>();
  }
  return it;
}

QualityZone zone(const json& j, const std::string& where) {
  QualityZone z;
  z.quality = integer(field(j, "quality", where), where + " quality");
  z.shape = shape(field(j, "shape", where), where + " shape").outer;
  return z;
}

Bin bin(const json& j, const std::string& source) {
  const std::string where0 = source + " bin";
  Bin b;
  b.id = integer(field(j, "id", where0), where0 + " id");
  const std::string where = source + " hide " + std::to_string(b.id);
  if (j.contains("shape")) {
    RingsWithHoles rings = shape(j["shape"], where + " shape");
    b.outer = std::move(rings.outer);
    b.holes = std::move(rings.holes);
  } else {
    b.outer = ring(field(j, "outer", where), where + " outer");
    if (j.contains("holes"))
      for (const json& h : j["holes"]) b.holes.push_back(ring(h, where + " hole"));
  }
  make_counter_clockwise(b.outer);
  if (j.contains("zones")) {
    if (!j["zones"].is_array()) fail(where, "\"zones\" must be a list");
    for (const json& z : j["zones"]) b.zones.push_back(zone(z, where + " zone"));
  }
  if (j.contains("stock")) b.stock = integer(j["stock"], where + " stock");
  if (b.stock < 0) fail(where, "stock is negative");
  if (j.contains("cost")) b.cost = number(j["cost"], where + " cost");
  if (j.contains("name") && !j["name"].is_null()) {
    if (!j["name"].is_string()) fail(where, "\"name\" must be text");
    b.name = j["name"].get<std::string>();
  }
  if (j.contains("backbone_deg") && !j["backbone_deg"].is_null()) b.backbone_deg = number(j["backbone_deg"], where + " backbone_deg");
  if (j.contains("backbone_point") && !j["backbone_point"].is_null()) b.backbone_point = point(j["backbone_point"], where + " backbone_point");
  return b;
}

void check_unique_ids(const NestInstance& instance, const std::string& source) {
  std::set<int> items, bins;
  for (const NestItem& it : instance.items)
    if (!items.insert(it.id).second) fail(source, "item id " + std::to_string(it.id) + " appears twice");
  for (const Bin& b : instance.bins)
    if (!bins.insert(b.id).second) fail(source, "hide id " + std::to_string(b.id) + " appears twice");
}

json item_json(const NestItem& it) {
  json j = {{"id", it.id}, {"shape", ring_json(it.shape)}, {"demand", it.demand}, {"label", it.label},
            {"allow_mirror", it.allow_mirror}, {"min_quality", it.min_quality}};
  if (!it.allowed_rotations_deg.empty()) j["allowed_rotations_deg"] = it.allowed_rotations_deg;
  if (it.grain_deg) {
    j["grain_deg"] = *it.grain_deg;
    j["grain_tolerance_deg"] = it.grain_tolerance_deg;
  }
  json marks = json::array();
  for (const ItemMark& m : it.marks)
    marks.push_back({{"name", m.name}, {"from", {m.from_mm.x(), m.from_mm.y()}}, {"to", {m.to_mm.x(), m.to_mm.y()}}});
  j["marks"] = marks;
  if (!it.drawn_lines_mm.empty()) {
    json lines = json::array();
    for (const std::vector<Point2>& line : it.drawn_lines_mm) {
      lines.push_back(json::array());
      for (const Point2& p : line) lines.back().push_back({p.x(), p.y()});
    }
    j["drawn_lines"] = lines;
  }
  if (!it.quality_regions.empty()) {
    json regions = json::array();
    for (const QualityRegion& r : it.quality_regions) regions.push_back({{"min_quality", r.min_quality}, {"shape", ring_json(r.shape)}});
    j["quality_regions"] = regions;
  }
  if (!it.pair_group.empty()) j["pair_group"] = it.pair_group;
  if (it.priority != 0) j["priority"] = it.priority;
  if (!it.mirror_key.empty()) j["mirror_key"] = it.mirror_key;
  return j;
}

json bin_json(const Bin& b) {
  json holes = json::array(), zones = json::array();
  for (const Polygon2& h : b.holes) holes.push_back(ring_json(h));
  for (const QualityZone& z : b.zones) zones.push_back({{"quality", z.quality}, {"shape", ring_json(z.shape)}});
  json j = {{"id", b.id}, {"outer", ring_json(b.outer)}, {"holes", holes}, {"zones", zones}, {"stock", b.stock}, {"cost", b.cost}};
  if (!b.name.empty()) j["name"] = b.name;
  if (b.backbone_deg) j["backbone_deg"] = *b.backbone_deg;
  if (b.backbone_point) j["backbone_point"] = {b.backbone_point->x(), b.backbone_point->y()};
  return j;
}

double optional_number(const json& j, const char* key, const std::string& where) {
  return j.contains(key) ? number(j[key], where + " " + key) : 0.0;
}

}  // namespace

NestInstance instance_from_json(const json& j, const std::string& source) {
  if (!j.is_object()) fail(source, "a nest instance must be a JSON object");
  NestInstance instance;
  instance.name = j.contains("name") && j["name"].is_string() ? j["name"].get<std::string>() : source;
  if (j.contains("strip_height") && !j["strip_height"].is_null()) {
    instance.strip_height = number(j["strip_height"], source + " strip_height");
    if (*instance.strip_height <= 0) fail(source, "strip_height must be positive");
  }
  instance.items = items_from_json(j, source);
  if (j.contains("bins")) {
    if (!j["bins"].is_array()) fail(source, "\"bins\" must be a list");
    for (const json& b : j["bins"]) instance.bins.push_back(bin(b, source));
  }
  if (!instance.strip_height && instance.bins.empty()) fail(source, "neither \"strip_height\" nor \"bins\": nothing to nest on");
  if (instance.strip_height && !instance.bins.empty()) fail(source, "both \"strip_height\" and \"bins\": choose a strip or hides");
  instance.gap_mm = optional_number(j, "gap_mm", source);
  instance.margin_mm = optional_number(j, "margin_mm", source);
  instance.pair_distance_mm = optional_number(j, "pair_distance_mm", source);
  if (instance.gap_mm < 0 || instance.margin_mm < 0) fail(source, "gap and margin must not be negative");
  if (instance.pair_distance_mm < 0) fail(source, "pair_distance_mm must not be negative");
  check_unique_ids(instance, source);
  return instance;
}

json read_json_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw EngineError("cannot open " + path.string());
  try {
    return json::parse(in);
  } catch (const json::parse_error& error) {
    throw EngineError(path.string() + " is not valid JSON (byte " + std::to_string(error.byte) + ")");
  } catch (const json::out_of_range&) {
    // nlohmann's parser refuses a number too large for a double (1e400) with out_of_range, not parse_error.
    throw EngineError(path.string() + " holds a number too large to be read");
  }
}

NestInstance read_nest_instance(const std::filesystem::path& path) {
  NestInstance instance = instance_from_json(read_json_file(path), path.filename().string());
  return instance;
}

Bin bin_from_json(const json& j, const std::string& source) { return bin(j, source); }

json items_to_json(const std::vector<NestItem>& items) {
  json list = json::array();
  for (const NestItem& it : items) list.push_back(item_json(it));
  return {{"items", list}};
}

std::vector<NestItem> items_from_json(const json& j, const std::string& source) {
  if (!j.is_object()) fail(source, "expected a JSON object with \"items\"");
  const json& list = field(j, "items", source);
  if (!list.is_array()) fail(source, "\"items\" must be a list");
  std::vector<NestItem> items;
  for (const json& it : list) items.push_back(item(it, source));
  return items;
}

json instance_to_json(const NestInstance& instance) {
  json j = {{"name", instance.name}, {"gap_mm", instance.gap_mm}, {"margin_mm", instance.margin_mm}};
  if (instance.pair_distance_mm > 0) j["pair_distance_mm"] = instance.pair_distance_mm;
  j["items"] = items_to_json(instance.items).at("items");
  if (instance.strip_height) {
    j["strip_height"] = *instance.strip_height;
  } else {
    json bins = json::array();
    for (const Bin& b : instance.bins) bins.push_back(bin_json(b));
    j["bins"] = bins;
  }
  return j;
}

json layout_to_json(const Layout& layout, const NestInstance& instance) {
  json j = instance_to_json(instance);
  j.erase("name");
  j["instance"] = layout.instance;
  if (layout.strip_length) j["strip_length"] = *layout.strip_length;
  j["utilisation"] = layout.utilisation;
  json placements = json::array();
  for (const Placement& p : layout.placements) {
    json pj = {{"item", p.item}, {"rotation_deg", p.rotation_deg}, {"mirrored", p.mirrored}, {"x", p.x}, {"y", p.y}};
    if (p.bin >= 0) pj["bin"] = p.bin;
    if (p.copy > 0) pj["copy"] = p.copy;
    placements.push_back(pj);
  }
  j["placements"] = placements;
  json unplaced = json::array();
  for (const Unplaced& u : layout.unplaced) unplaced.push_back({{"item", u.item}, {"count", u.count}, {"reason", u.reason}});
  j["unplaced"] = unplaced;
  return j;
}

Layout layout_from_json(const json& j) {
  const std::string where = "layout";
  if (!j.is_object()) fail(where, "a layout must be a JSON object");
  Layout layout;
  if (j.contains("instance") && j["instance"].is_string()) layout.instance = j["instance"].get<std::string>();
  if (j.contains("strip_length") && !j["strip_length"].is_null()) layout.strip_length = number(j["strip_length"], where + " strip_length");
  if (j.contains("utilisation")) layout.utilisation = number(j["utilisation"], where + " utilisation");
  const json& placements = field(j, "placements", where);
  if (!placements.is_array()) fail(where, "\"placements\" must be a list");
  for (const json& pj : placements) {
    const std::string pw = where + " placement " + std::to_string(layout.placements.size());
    Placement p;
    p.item = integer(field(pj, "item", pw), pw + " item");
    if (pj.contains("bin")) p.bin = integer(pj["bin"], pw + " bin");
    if (pj.contains("copy")) p.copy = integer(pj["copy"], pw + " copy");
    p.rotation_deg = number(field(pj, "rotation_deg", pw), pw + " rotation_deg");
    if (pj.contains("mirrored")) {
      if (!pj["mirrored"].is_boolean()) fail(pw, "\"mirrored\" must be true or false");
      p.mirrored = pj["mirrored"].get<bool>();
    }
    p.x = number(field(pj, "x", pw), pw + " x");
    p.y = number(field(pj, "y", pw), pw + " y");
    layout.placements.push_back(p);
  }
  if (j.contains("unplaced")) {
    if (!j["unplaced"].is_array()) fail(where, "\"unplaced\" must be a list");
    for (const json& uj : j["unplaced"]) {
      Unplaced u;
      u.item = integer(field(uj, "item", where + " unplaced"), where + " unplaced item");
      u.count = integer(field(uj, "count", where + " unplaced"), where + " unplaced count");
      if (uj.contains("reason") && uj["reason"].is_string()) u.reason = uj["reason"].get<std::string>();
      layout.unplaced.push_back(u);
    }
  }
  return layout;
}

NestInstance instance_from_layout_json(const json& j) {
  if (!j.is_object()) fail("layout", "a layout must be a JSON object");
  json copy = j;
  copy["name"] = j.contains("instance") && j["instance"].is_string() ? j["instance"].get<std::string>() : "layout";
  if (!copy.contains("items")) fail("layout", "no embedded \"items\": write layouts with layout_to_json");
  return instance_from_json(copy, "layout");
}

void write_layout(const std::filesystem::path& path, const Layout& layout, const NestInstance& instance) {
  std::ofstream out(path);
  if (!out) throw EngineError("cannot write layout " + path.string());
  out << layout_to_json(layout, instance).dump(1) << '\n';
  if (!out) throw EngineError("writing layout " + path.string() + " failed");
}

}  // namespace lastcut
