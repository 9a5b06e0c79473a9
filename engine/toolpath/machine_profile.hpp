#pragma once
// MachineProfile: everything lastcut must know about one cutting machine to write its cut file:
// table size, the tools (knife, mark, pen) and how to switch them, speeds, blade offset, corner
// thresholds and the options of its dialect (HPGL or grbl G-code). Profiles are TOML files in
// config/machines/ (every key is documented there); unknown keys are errors so that a typo in
// a profile never silently falls back to a default.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "engine/toolpath/cut_program.hpp"

namespace lastcut {

enum class CutFileFormat { Hpgl, Gcode, Dxf, Svg };
// "hpgl" | "gcode" | "dxf" | "svg"; throws EngineError for anything else.
CutFileFormat parse_cut_file_format(const std::string& name);
std::string to_string(CutFileFormat format);

enum class ToolKind {
  Pen,              // draws; no compensation
  DragKnife,        // blade trails the holder axis by blade_offset_mm: compensated with corner arcs
  TangentialKnife,  // blade turned by a rotary axis to follow the path; lifted at sharp corners
};

struct ToolSettings {
  ToolKind kind = ToolKind::Pen;
  double speed_mm_s = 50.0;        // tool-down feed
  double plunge_speed_mm_s = 10.0; // G-code: Z feed when going down
  double blade_offset_mm = 0.0;    // drag knife: distance from holder axis to blade tip (mm)
  int hpgl_pen = 1;                // HPGL: SP number selecting this tool
  // G-code: a tool is put down either by Z moves (to z_down_mm, back to gcode.z_up_mm) or, when
  // gcode_down and gcode_up are given, by those lines (M3/M5, M7/M8/M9 driving a solenoid).
  double z_down_mm = 0.0;
  std::string gcode_down;
  std::string gcode_up;
  bool uses_z() const { return gcode_down.empty(); }
};

struct HpglOptions {
  double units_per_mm = 40.0;        // plotter units per mm (HP: 40, i.e. 0.025 mm)
  int max_points_per_command = 32;   // PD coordinate pairs per command, for small input buffers
  int max_line_length = 72;          // characters per line before a line break (0: no breaks)
  bool send_velocity = true;         // VS per tool (cm/s, HPGL's unit)
};

struct GcodeOptions {
  double z_up_mm = 5.0;                 // Z for travel and corner lifts of tools moved by Z
  std::string rotary_axis;              // "", "A" or "C": axis word for a tangential knife
  bool arc_fitting = false;             // replace runs of points by G2/G3 arcs
  double arc_tolerance_mm = 0.01;       // max distance of every replaced point from its arc
  int decimals = 3;                     // digits after the decimal point
  std::string program_start;            // extra lines after G21 G90 (e.g. "G54"), may be empty
  std::string program_end;              // extra lines before M2, may be empty
};

struct LabelOptions {
  bool enabled = true;
  double height_mm = 6.0;      // preferred letter height
  double min_height_mm = 2.5;  // smallest letter height tried before giving up on a small piece
};

// How the mark tool cuts a notch ([notch]; which marks are notches: mark_stroke.hpp).
enum class NotchShape {
  Slit,  // one stroke from the outline straight in to the notch's inner end
  V,     // one stroke: outline point - half the width, inner end, outline point + half the width
};

struct NotchOptions {
  NotchShape shape = NotchShape::Slit;
  double v_width_mm = 2.0;  // V: the opening at the outline, measured across the notch
};

struct MachineProfile {
  std::string name;
  CutFileFormat native_format = CutFileFormat::Gcode;
  double work_area_x_mm = 1000.0;
  double work_area_y_mm = 1000.0;
  double travel_speed_mm_s = 200.0;
  double overcut_mm = 1.0;             // cut past the start point to close the outline
  double corner_threshold_deg = 30.0;  // drag: turns above get a swivel arc; tangential: lift
  double drag_arc_step_deg = 10.0;     // angular step of drag-knife swivel arcs
  ToolSettings cut;
  std::optional<ToolSettings> mark;  // absent: marks are cut with the cut tool
  std::optional<ToolSettings> pen;   // absent: no labels are drawn
  HpglOptions hpgl;
  GcodeOptions gcode;
  LabelOptions label;
  NotchOptions notch;

  // The settings of the tool that performs `role` (mark falls back to cut). Throws EngineError
  // for Pen when the profile has no pen.
  const ToolSettings& tool(ToolRole role) const;
};

// Parses a profile from TOML text; `origin` names the source in error messages.
// Throws EngineError with one line ("grbl-x.toml: unknown key 'tools.cut.sped'").
MachineProfile parse_machine_profile(const std::string& toml_text, const std::string& origin);

// path_or_name: a path to a .toml file, or a profile name looked up as <dir>/<name>.toml in
// search_dirs, in order. Throws EngineError naming the places searched when nothing is found.
MachineProfile load_machine_profile(const std::string& path_or_name,
                                    const std::vector<std::filesystem::path>& search_dirs);

// Where profiles live: the source tree's config/machines (fixed at build time), then
// /etc/lastcut/machines.
std::vector<std::filesystem::path> standard_machine_profile_dirs();

}  // namespace lastcut
