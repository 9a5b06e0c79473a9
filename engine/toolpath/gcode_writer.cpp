#include "engine/toolpath/gcode_writer.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "engine/core/engine_error.hpp"
#include "engine/toolpath/arc_fit.hpp"

namespace lastcut {
namespace {

class GcodeOut {
 public:
  explicit GcodeOut(int decimals) : decimals_(decimals) {}

  std::string number(double value) const {
    if (!std::isfinite(value)) throw EngineError("a G-code coordinate is not a number");
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals_, value);
    std::string text(buffer);
    if (text.find('.') != std::string::npos) {
      while (text.back() == '0') text.pop_back();
      if (text.back() == '.') text.pop_back();
    }
    return text == "-0" ? "0" : text;
  }
  std::string xy(const Point2& point_mm) const { return "X" + number(point_mm.x()) + " Y" + number(point_mm.y()); }
  void line(const std::string& text) { out_ << text << "\n"; }
  std::string text() const { return out_.str(); }
  std::size_t size() { return static_cast<std::size_t>(out_.tellp()); }

 private:
  int decimals_;
  std::ostringstream out_;
};

std::string feed(double speed_mm_s, const GcodeOut& out) { return " F" + out.number(speed_mm_s * 60.0); }

// "; TEXT" with TEXT made printable ASCII and the line cut to 72 characters, so that no controller
// reads part of a label as a command and a character-counting sender never has to fit a long line
// into grbl's 128-byte receive buffer.
std::string comment_line(const std::string& text) {
  std::string line = "; ";
  for (const char c : text) line += (c >= 32 && c < 127) ? c : '?';
  constexpr size_t kLongestComment = 72;
  if (line.size() > kLongestComment) line = line.substr(0, kLongestComment - 3) + "...";
  return line;
}

// "; piece 3/20: m-38-left lateral (item 0)": where the operator (and a G-code viewer) sees which
// piece the next moves cut.
std::string piece_comment(const CutProgram& program, int piece) {
  const ProgramPiece& p = program.pieces[static_cast<size_t>(piece)];
  const std::string& label = p.label.empty() ? p.marking : p.label;
  return comment_line("piece " + std::to_string(piece + 1) + "/" + std::to_string(program.pieces.size()) + ": " +
                      (label.empty() ? "" : label + " ") + "(item " + std::to_string(p.item_id) + ")");
}

}  // namespace

std::string write_gcode(const CutProgram& program, const MachineProfile& profile, std::vector<std::size_t>* stroke_offsets) {
  const GcodeOptions& options = profile.gcode;
  GcodeOut out(options.decimals);
  const std::string& axis = options.rotary_axis;
  out.line("; lastcut cut file for machine '" + profile.name + "': " + std::to_string(program.pieces.size()) +
           " pieces");
  for (const std::string& note : program.notes) out.line(comment_line(note));
  out.line("G21 G90 G94");
  out.line("G17");
  if (!options.program_start.empty()) out.line(options.program_start);
  out.line("G0 Z" + out.number(options.z_up_mm));

  int piece = -1;  // whose moves follow
  for (const Stroke& stroke : program.strokes) {
    if (stroke_offsets) stroke_offsets->push_back(out.size());
    if (stroke.points_mm.size() < 2) continue;
    if (stroke.piece >= 0 && stroke.piece != piece && static_cast<size_t>(stroke.piece) < program.pieces.size()) {
      piece = stroke.piece;
      out.line(piece_comment(program, piece));
    }
    const ToolSettings& tool = profile.tool(stroke.tool);
    const bool with_angle = !axis.empty() && stroke.knife_angle_deg.size() == stroke.points_mm.size();
    std::string travel = "G0 " + out.xy(stroke.points_mm.front());
    if (with_angle) travel += " " + axis + out.number(stroke.knife_angle_deg.front());
    out.line(travel);
    if (tool.uses_z()) {
      out.line("G1 Z" + out.number(tool.z_down_mm) + feed(tool.plunge_speed_mm_s, out));
    } else {
      out.line(tool.gcode_down);
    }
    const std::string cut_feed = feed(tool.speed_mm_s, out);
    bool feed_written = false;
    auto with_feed = [&](std::string move) {
      if (!feed_written) move += cut_feed;
      feed_written = true;
      return move;
    };
    if (with_angle || !options.arc_fitting) {
      for (size_t k = 1; k < stroke.points_mm.size(); ++k) {
        const bool moves = (stroke.points_mm[k] - stroke.points_mm[k - 1]).norm() > 0.0;
        std::string move = "G1";
        if (moves) move += " " + out.xy(stroke.points_mm[k]);
        if (with_angle && stroke.knife_angle_deg[k] != stroke.knife_angle_deg[k - 1]) {
          move += " " + axis + out.number(stroke.knife_angle_deg[k]);
        }
        if (move != "G1") out.line(with_feed(move));
      }
    } else {
      Point2 at = stroke.points_mm.front();
      for (const PathSegment& segment : fit_arcs(stroke.points_mm, ArcFitOptions{options.arc_tolerance_mm})) {
        if (segment.is_arc) {
          const Point2 offset = segment.center_mm - at;
          out.line(with_feed(std::string(segment.counter_clockwise ? "G3 " : "G2 ") + out.xy(segment.end_mm) +
                             " I" + out.number(offset.x()) + " J" + out.number(offset.y())));
        } else {
          out.line(with_feed("G1 " + out.xy(segment.end_mm)));
        }
        at = segment.end_mm;
      }
    }
    if (tool.uses_z()) {
      out.line("G0 Z" + out.number(options.z_up_mm));
    } else {
      out.line(tool.gcode_up);
    }
  }
  if (stroke_offsets) stroke_offsets->push_back(out.size());
  out.line("G0 X0 Y0");
  if (!options.program_end.empty()) out.line(options.program_end);
  out.line("M2");
  return out.text();
}

}  // namespace lastcut
