#pragma once
// Running lastcut's cut files through interpreters nobody on the project wrote: hp2xx for HPGL
// (gnuplot output, true size), cncjs' gcode-parser + gcode-toolpath under node for G-code, and
// dxf-parser under node for DXF.
// A missing tool is a test failure (FAIL, never skip): the helpers throw std::runtime_error.
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut::test {

// One pen-down run as the interpreter saw it (mm).
struct InterpretedPath {
  std::vector<Point2> points_mm;
};

// hp2xx -t -m gpt: every PU-started, PD-continued polyline in mm (true size, absolute: the
// offset hp2xx subtracts is read back from its "Coordinate range" report).
std::vector<InterpretedPath> hpgl_paths_via_hp2xx(const std::filesystem::path& hpgl_file, double units_per_mm);

// One G-code move as gcode-toolpath saw it. Arcs carry their centre; a1/a2 is the rotary axis.
struct GcodeMove {
  std::string motion;  // G0, G1, G2, G3
  Point2 from_mm = Point2::Zero(), to_mm = Point2::Zero();
  double z_from_mm = 0, z_to_mm = 0;
  bool is_arc = false;
  Point2 center_mm = Point2::Zero();
  double a_from_deg = 0, a_to_deg = 0;
  std::string spindle, coolant;
};

std::vector<GcodeMove> gcode_moves_via_node(const std::filesystem::path& gcode_file, const std::string& rotary_axis);

// Points along a move: lines give their end, arcs are sampled every <= 1 degree (end included).
std::vector<Point2> sample_move(const GcodeMove& move);

// A DXF file as dxf-parser (npm) read it: header, layer table, entities with their points (mm).
struct ParsedDxfEntity {
  std::string type, layer;
  bool closed = false;             // a polyline's closed flag
  std::vector<Point2> points_mm;   // polyline vertices, LINE start/end, TEXT insertion point
  std::string text;
};
struct ParsedDxf {
  std::string acadver;
  int insunits = 0;
  std::vector<std::string> layers;
  std::vector<ParsedDxfEntity> entities;
};
ParsedDxf dxf_via_node(const std::filesystem::path& dxf_file);

// Runs a shell command, returns stdout; throws with stderr's tail when it exits non-zero.
std::string run_command(const std::string& command);

}  // namespace lastcut::test
