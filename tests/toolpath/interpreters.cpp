#include "interpreters.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>

#include "tests/support/temp_dir.hpp"
#include "tests/toolpath/test_layouts.hpp"

namespace lastcut::test {
namespace {

}  // namespace

std::string run_command(const std::string& command) {
  const TempDir folder("interpreter");
  const std::filesystem::path errors = folder / "stderr.txt";
  const std::string full = command + " 2>" + errors.string();
  FILE* pipe = ::popen(full.c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run: " + command);
  std::string output;
  std::array<char, 65536> buffer;
  size_t count;
  while ((count = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) output.append(buffer.data(), count);
  const int status = ::pclose(pipe);
  const std::string stderr_text = read_text(errors);
  if (status != 0) {
    throw std::runtime_error("command failed (status " + std::to_string(WEXITSTATUS(status)) + "): " + command +
                             "\n" + stderr_text.substr(0, 2000));
  }
  return output + "\n#STDERR\n" + stderr_text;
}

std::vector<InterpretedPath> hpgl_paths_via_hp2xx(const std::filesystem::path& hpgl_file, double units_per_mm) {
  const std::string text = run_command("hp2xx -t -m gpt -f - '" + hpgl_file.string() + "'");
  const size_t split = text.rfind("\n#STDERR\n");
  const std::string plot = text.substr(0, split);
  const std::string report = text.substr(split);
  std::smatch range;
  const std::regex range_pattern(R"(Coordinate range: \((-?[0-9.]+), (-?[0-9.]+)\))");
  if (!std::regex_search(report, range, range_pattern)) {
    throw std::runtime_error("hp2xx printed no coordinate range:\n" + report.substr(0, 1000));
  }
  const Point2 offset_mm(std::stod(range[1]) / units_per_mm, std::stod(range[2]) / units_per_mm);

  std::vector<InterpretedPath> paths;
  std::istringstream lines(plot);
  std::string line;
  std::string mode;
  std::vector<Point2> current;
  auto flush = [&] {
    if (current.size() >= 2) paths.push_back(InterpretedPath{current});
    current.clear();
  };
  while (std::getline(lines, line)) {
    if (line.rfind("#PU", 0) == 0 || line.rfind("#PD", 0) == 0) {
      mode = line.substr(0, 3);
      continue;
    }
    if (line.empty() || line[0] == '#') continue;
    double x, y;
    if (std::sscanf(line.c_str(), "%lf %lf", &x, &y) != 2) continue;
    const Point2 point = Point2(x, y) + offset_mm;
    if (mode == "#PU") {
      // hp2xx's gnuplot output restarts a long pen-down run every few points with a "#PU" at
      // the current position: the pen never left the paper there, so the run continues.
      if (!current.empty() && (point - current.back()).norm() < 1e-9) continue;
      flush();
      current.push_back(point);
    } else if (mode == "#PD") {
      current.push_back(point);
    }
  }
  flush();
  return paths;
}

std::vector<GcodeMove> gcode_moves_via_node(const std::filesystem::path& gcode_file, const std::string& rotary_axis) {
  const std::string script = std::string(LASTCUT_SOURCE_DIR) + "/tests/toolpath/gcode_dump.js";
  const std::string modules = std::string(LASTCUT_SOURCE_DIR) + "/tests/node/node_modules";
  const std::string text = run_command("node '" + script + "' '" + gcode_file.string() + "' '" + modules + "' " +
                                       (rotary_axis.empty() ? "A" : rotary_axis));
  const nlohmann::json json = nlohmann::json::parse(text.substr(0, text.rfind("\n#STDERR\n")));
  std::vector<GcodeMove> moves;
  for (const auto& item : json.at("moves")) {
    GcodeMove move;
    move.motion = item.at("motion").get<std::string>();
    move.from_mm = Point2(item.at("x1").get<double>(), item.at("y1").get<double>());
    move.to_mm = Point2(item.at("x2").get<double>(), item.at("y2").get<double>());
    move.z_from_mm = item.at("z1").get<double>();
    move.z_to_mm = item.at("z2").get<double>();
    move.is_arc = item.contains("cx");
    if (move.is_arc) move.center_mm = Point2(item.at("cx").get<double>(), item.at("cy").get<double>());
    move.a_from_deg = item.at("a1").get<double>();
    move.a_to_deg = item.at("a2").get<double>();
    move.spindle = item.at("spindle").get<std::string>();
    move.coolant = item.at("coolant").get<std::string>();
    moves.push_back(move);
  }
  return moves;
}

ParsedDxf dxf_via_node(const std::filesystem::path& dxf_file) {
  const std::string script = std::string(LASTCUT_SOURCE_DIR) + "/tests/toolpath/dxf_dump.js";
  const std::string modules = std::string(LASTCUT_SOURCE_DIR) + "/tests/node/node_modules";
  const std::string text = run_command("node '" + script + "' '" + dxf_file.string() + "' '" + modules + "'");
  const nlohmann::json json = nlohmann::json::parse(text.substr(0, text.rfind("\n#STDERR\n")));
  ParsedDxf dxf;
  dxf.acadver = json.at("acadver").get<std::string>();
  dxf.insunits = json.at("insunits").get<int>();
  dxf.layers = json.at("layers").get<std::vector<std::string>>();
  for (const auto& item : json.at("entities")) {
    ParsedDxfEntity entity;
    entity.type = item.at("type").get<std::string>();
    entity.layer = item.at("layer").get<std::string>();
    entity.closed = item.at("closed").get<bool>();
    for (const auto& point : item.at("points")) entity.points_mm.emplace_back(point.at(0).get<double>(), point.at(1).get<double>());
    entity.text = item.at("text").get<std::string>();
    dxf.entities.push_back(std::move(entity));
  }
  return dxf;
}

std::vector<Point2> sample_move(const GcodeMove& move) {
  if (!move.is_arc) return {move.to_mm};
  const Point2 from = move.from_mm - move.center_mm, to = move.to_mm - move.center_mm;
  const double radius = from.norm();
  const double start = std::atan2(from.y(), from.x());
  double sweep = std::atan2(to.y(), to.x()) - start;
  const bool ccw = move.motion == "G3";
  if (ccw && sweep <= 0) sweep += 2 * std::numbers::pi;
  if (!ccw && sweep >= 0) sweep -= 2 * std::numbers::pi;
  const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / (std::numbers::pi / 180.0))));
  std::vector<Point2> points;
  for (int s = 1; s <= steps; ++s) {
    const double angle = start + sweep * s / steps;
    points.push_back(move.center_mm + radius * Point2(std::cos(angle), std::sin(angle)));
  }
  points.back() = move.to_mm;
  return points;
}

}  // namespace lastcut::test
