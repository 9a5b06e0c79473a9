// Reading machine profiles (TOML, toml++). Every table is read through a KeyReader that remembers
// which keys it was asked for; whatever remains in the file afterwards is an unknown key and an
// error, because a misspelt key silently replaced by a default would cut at the wrong speed.
#include "engine/toolpath/machine_profile.hpp"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#define TOML_EXCEPTIONS 1
#include <toml++/toml.h>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

class KeyReader {
 public:
  KeyReader(const toml::table* table, std::string path, std::string origin)
      : table_(table), path_(std::move(path)), origin_(std::move(origin)) {}

  double number(const std::string& key, double fallback, double min_value, double max_value) {
    const toml::node* node = find(key);
    if (!node) return fallback;
    const std::optional<double> value = node->value<double>();
    if (!value || !std::isfinite(*value)) fail(key, "must be a number");
    if (*value < min_value || *value > max_value) {
      std::ostringstream range;
      range << "must be between " << min_value << " and " << max_value;
      fail(key, range.str());
    }
    return *value;
  }
  int integer(const std::string& key, int fallback, int min_value, int max_value) {
    const toml::node* node = find(key);
    if (!node) return fallback;
    const std::optional<int64_t> value = node->is_integer() ? node->value<int64_t>() : std::nullopt;
    if (!value) fail(key, "must be a whole number");
    if (*value < min_value || *value > max_value) {
      fail(key, "must be between " + std::to_string(min_value) + " and " + std::to_string(max_value));
    }
    return static_cast<int>(*value);
  }
  bool boolean(const std::string& key, bool fallback) {
    const toml::node* node = find(key);
    if (!node) return fallback;
    if (!node->is_boolean()) fail(key, "must be true or false");
    return *node->value<bool>();
  }
  std::string text(const std::string& key, const std::string& fallback) {
    const toml::node* node = find(key);
    if (!node) return fallback;
    if (!node->is_string()) fail(key, "must be a string in quotes");
    return *node->value<std::string>();
  }
  std::string choice(const std::string& key, const std::string& fallback, const std::set<std::string>& allowed) {
    std::string value = text(key, fallback);
    if (!allowed.count(value)) {
      std::string list;
      for (const std::string& option : allowed) list += (list.empty() ? "\"" : ", \"") + option + "\"";
      fail(key, "must be one of " + list);
    }
    return value;
  }
  const toml::table* sub_table(const std::string& key) {
    const toml::node* node = find(key);
    if (!node) return nullptr;
    if (!node->is_table()) fail(key, "must be a table [" + qualified(key) + "]");
    return node->as_table();
  }
  bool has(const std::string& key) const { return table_ && table_->contains(key); }
  KeyReader child(const std::string& key) { return KeyReader(sub_table(key), qualified(key), origin_); }

  // Throws for the first key of the table that nobody asked for.
  void reject_unknown_keys() const {
    if (!table_) return;
    for (const auto& [key, node] : *table_) {
      const std::string name(key.str());
      if (!known_.count(name)) {
        throw EngineError(origin_ + ": unknown key '" + qualified(name) + "'");
      }
    }
  }

  [[noreturn]] void fail(const std::string& key, const std::string& why) const {
    throw EngineError(origin_ + ": '" + qualified(key) + "' " + why);
  }

 private:
  const toml::node* find(const std::string& key) {
    known_.insert(key);
    return table_ ? table_->get(key) : nullptr;
  }
  std::string qualified(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  const toml::table* table_;
  std::string path_;
  std::string origin_;
  std::set<std::string> known_;
};

ToolSettings read_tool(KeyReader& tools, const std::string& role_name) {
  KeyReader reader = tools.child(role_name);
  ToolSettings tool;
  const std::string kind = reader.choice("kind", "pen", {"pen", "drag_knife", "tangential_knife"});
  tool.kind = kind == "drag_knife"         ? ToolKind::DragKnife
              : kind == "tangential_knife" ? ToolKind::TangentialKnife
                                           : ToolKind::Pen;
  tool.speed_mm_s = reader.number("speed_mm_s", tool.speed_mm_s, 0.1, 5000.0);
  tool.plunge_speed_mm_s = reader.number("plunge_speed_mm_s", tool.plunge_speed_mm_s, 0.1, 5000.0);
  tool.blade_offset_mm = reader.number("blade_offset_mm", 0.0, 0.0, 5.0);
  if (tool.kind != ToolKind::DragKnife && tool.blade_offset_mm > 0.0) {
    reader.fail("blade_offset_mm", "only applies to kind = \"drag_knife\"");
  }
  tool.hpgl_pen = reader.integer("hpgl_pen", tool.hpgl_pen, 0, 99);
  tool.z_down_mm = reader.number("z_down_mm", tool.z_down_mm, -100.0, 100.0);
  tool.gcode_down = reader.text("gcode_down", "");
  tool.gcode_up = reader.text("gcode_up", "");
  if (tool.gcode_down.empty() != tool.gcode_up.empty()) {
    reader.fail(tool.gcode_down.empty() ? "gcode_down" : "gcode_up", "must be given together with its partner");
  }
  for (const std::string* line : {&tool.gcode_down, &tool.gcode_up}) {
    if (line->find_first_of("\r\n;(") != std::string::npos) {
      reader.fail(line == &tool.gcode_down ? "gcode_down" : "gcode_up", "must be one G-code line without comments");
    }
  }
  reader.reject_unknown_keys();
  return tool;
}

}  // namespace

CutFileFormat parse_cut_file_format(const std::string& name) {
  if (name == "hpgl") return CutFileFormat::Hpgl;
  if (name == "gcode") return CutFileFormat::Gcode;
  if (name == "dxf") return CutFileFormat::Dxf;
  if (name == "svg") return CutFileFormat::Svg;
  throw EngineError("unknown cut file format '" + name + "' (use hpgl, gcode, dxf or svg)");
}

std::string to_string(CutFileFormat format) {
  switch (format) {
    case CutFileFormat::Hpgl: return "hpgl";
    case CutFileFormat::Gcode: return "gcode";
    case CutFileFormat::Dxf: return "dxf";
    case CutFileFormat::Svg: return "svg";
  }
  return "gcode";
}

const ToolSettings& MachineProfile::tool(ToolRole role) const {
  switch (role) {
    case ToolRole::Cut: return cut;
    case ToolRole::Mark: return mark ? *mark : cut;
    case ToolRole::Pen:
      if (!pen) throw EngineError("machine profile '" + name + "' has no pen for labels");
      return *pen;
  }
  return cut;
}

MachineProfile parse_machine_profile(const std::string& toml_text, const std::string& origin) {
  toml::table document;
  try {
    document = toml::parse(toml_text, origin);
  } catch (const toml::parse_error& error) {
    throw EngineError(origin + ": line " + std::to_string(error.source().begin.line) + ": " +
                      std::string(error.description()));
  }
  KeyReader root(&document, "", origin);
  MachineProfile profile;

  KeyReader machine = root.child("machine");
  if (!root.has("machine")) root.fail("machine", "table is missing");
  profile.name = machine.text("name", "");
  if (profile.name.empty()) machine.fail("name", "is missing");
  profile.native_format = parse_cut_file_format(machine.choice("format", "gcode", {"gcode", "hpgl"}));
  profile.work_area_x_mm = machine.number("work_area_x_mm", profile.work_area_x_mm, 10.0, 20000.0);
  profile.work_area_y_mm = machine.number("work_area_y_mm", profile.work_area_y_mm, 10.0, 20000.0);
  profile.travel_speed_mm_s = machine.number("travel_speed_mm_s", profile.travel_speed_mm_s, 1.0, 5000.0);
  profile.overcut_mm = machine.number("overcut_mm", profile.overcut_mm, 0.0, 20.0);
  profile.corner_threshold_deg = machine.number("corner_threshold_deg", profile.corner_threshold_deg, 1.0, 179.0);
  profile.drag_arc_step_deg = machine.number("drag_arc_step_deg", profile.drag_arc_step_deg, 1.0, 45.0);
  machine.reject_unknown_keys();

  KeyReader tools = root.child("tools");
  if (!tools.has("cut")) tools.fail("cut", "table is missing");
  profile.cut = read_tool(tools, "cut");
  if (profile.cut.kind == ToolKind::Pen && profile.cut.blade_offset_mm > 0.0) tools.fail("cut", "pen with blade offset");
  if (tools.has("mark")) profile.mark = read_tool(tools, "mark");
  if (tools.has("pen")) profile.pen = read_tool(tools, "pen");
  tools.reject_unknown_keys();

  KeyReader hpgl = root.child("hpgl");
  profile.hpgl.units_per_mm = hpgl.number("units_per_mm", profile.hpgl.units_per_mm, 1.0, 1000.0);
  profile.hpgl.max_points_per_command =
      hpgl.integer("max_points_per_command", profile.hpgl.max_points_per_command, 1, 10000);
  profile.hpgl.max_line_length = hpgl.integer("max_line_length", profile.hpgl.max_line_length, 0, 100000);
  if (profile.hpgl.max_line_length > 0 && profile.hpgl.max_line_length < 24) {
    hpgl.fail("max_line_length", "must be 0 (no limit) or at least 24");
  }
  profile.hpgl.send_velocity = hpgl.boolean("send_velocity", profile.hpgl.send_velocity);
  hpgl.reject_unknown_keys();

  KeyReader gcode = root.child("gcode");
  profile.gcode.z_up_mm = gcode.number("z_up_mm", profile.gcode.z_up_mm, -100.0, 100.0);
  profile.gcode.rotary_axis = gcode.choice("rotary_axis", "", {"", "A", "C"});
  profile.gcode.arc_fitting = gcode.boolean("arc_fitting", profile.gcode.arc_fitting);
  profile.gcode.arc_tolerance_mm = gcode.number("arc_tolerance_mm", profile.gcode.arc_tolerance_mm, 0.001, 1.0);
  profile.gcode.decimals = gcode.integer("decimals", profile.gcode.decimals, 2, 6);
  profile.gcode.program_start = gcode.text("program_start", "");
  profile.gcode.program_end = gcode.text("program_end", "");
  gcode.reject_unknown_keys();

  KeyReader label = root.child("label");
  profile.label.enabled = label.boolean("enabled", profile.label.enabled && profile.pen.has_value());
  profile.label.height_mm = label.number("height_mm", profile.label.height_mm, 1.0, 100.0);
  profile.label.min_height_mm = label.number("min_height_mm", profile.label.min_height_mm, 0.5, 100.0);
  if (profile.label.min_height_mm > profile.label.height_mm) label.fail("min_height_mm", "must not exceed height_mm");
  if (profile.label.enabled && !profile.pen) label.fail("enabled", "needs a [tools.pen]");
  label.reject_unknown_keys();

  KeyReader notch = root.child("notch");
  profile.notch.shape = notch.choice("shape", "slit", {"slit", "v"}) == "v" ? NotchShape::V : NotchShape::Slit;
  profile.notch.v_width_mm = notch.number("v_width_mm", profile.notch.v_width_mm, 0.5, 10.0);
  notch.reject_unknown_keys();
  root.reject_unknown_keys();

  if (!profile.gcode.rotary_axis.empty() && profile.cut.kind != ToolKind::TangentialKnife) {
    gcode.fail("rotary_axis", "needs tools.cut.kind = \"tangential_knife\"");
  }
  return profile;
}

MachineProfile load_machine_profile(const std::string& path_or_name,
                                    const std::vector<std::filesystem::path>& search_dirs) {
  namespace fs = std::filesystem;
  if (path_or_name.empty()) throw EngineError("no machine profile given");
  std::vector<fs::path> candidates;
  const bool looks_like_path = path_or_name.find('/') != std::string::npos ||
                               fs::path(path_or_name).extension() == ".toml";
  if (looks_like_path) {
    candidates.emplace_back(path_or_name);
  } else {
    for (const fs::path& dir : search_dirs) candidates.push_back(dir / (path_or_name + ".toml"));
  }
  for (const fs::path& candidate : candidates) {
    std::error_code error;
    if (!fs::is_regular_file(candidate, error)) continue;
    std::ifstream in(candidate, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in.good() && !in.eof()) throw EngineError("cannot read machine profile " + candidate.string());
    return parse_machine_profile(text.str(), candidate.filename().string());
  }
  std::string searched;
  for (const fs::path& candidate : candidates) searched += (searched.empty() ? "" : ", ") + candidate.string();
  throw EngineError("machine profile '" + path_or_name + "' not found (looked at " + searched + ")");
}

std::vector<std::filesystem::path> standard_machine_profile_dirs() {
  return {std::filesystem::path(LASTCUT_MACHINE_PROFILE_DIR), std::filesystem::path("/etc/lastcut/machines")};
}

}  // namespace lastcut
