#include "engine/toolpath/hpgl_writer.hpp"

#include <cmath>
#include <sstream>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

class HpglOut {
 public:
  explicit HpglOut(const HpglOptions& options) : options_(options) {}

  std::string units(const Point2& point_mm) const {
    const double x = std::round(point_mm.x() * options_.units_per_mm);
    const double y = std::round(point_mm.y() * options_.units_per_mm);
    if (std::abs(x) > 8388607.0 || std::abs(y) > 8388607.0) {
      throw EngineError("coordinate beyond the HPGL range (+-8388607 plotter units)");
    }
    return std::to_string(static_cast<long long>(x)) + "," + std::to_string(static_cast<long long>(y));
  }
  void command(const std::string& text) { out_ << text << ";\n"; }
  // A PD/PU command with many pairs, split so that no command exceeds the limits.
  void pairs(const std::string& mnemonic, const std::vector<Point2>& points_mm) {
    std::string current;
    int count = 0;
    const size_t limit = options_.max_line_length > 0 ? static_cast<size_t>(options_.max_line_length) : SIZE_MAX;
    for (const Point2& point : points_mm) {
      const std::string pair = units(point);
      const size_t grown = mnemonic.size() + current.size() + (current.empty() ? 0 : 1) + pair.size() + 1;
      if (count > 0 && (count >= options_.max_points_per_command || grown > limit)) {
        command(mnemonic + current);
        current.clear();
        count = 0;
      }
      current += (current.empty() ? "" : ",") + pair;
      ++count;
    }
    if (count > 0) command(mnemonic + current);
  }
  std::string text() const { return out_.str(); }
  std::size_t size() { return static_cast<std::size_t>(out_.tellp()); }

 private:
  const HpglOptions& options_;
  std::ostringstream out_;
};

}  // namespace

std::string write_hpgl(const CutProgram& program, const MachineProfile& profile, std::vector<std::size_t>* stroke_offsets) {
  HpglOut out(profile.hpgl);
  out.command("IN");
  out.command("PA");
  int current_pen = -1;
  for (const Stroke& stroke : program.strokes) {
    if (stroke_offsets) stroke_offsets->push_back(out.size());
    if (stroke.points_mm.size() < 2) continue;
    const ToolSettings& tool = profile.tool(stroke.tool);
    if (tool.hpgl_pen != current_pen) {
      current_pen = tool.hpgl_pen;
      out.command("SP" + std::to_string(current_pen));
      if (profile.hpgl.send_velocity) {
        std::ostringstream velocity;
        velocity << "VS" << std::max(1.0, std::round(tool.speed_mm_s / 10.0 * 10.0) / 10.0);  // cm/s
        out.command(velocity.str());
      }
    }
    out.command("PU" + out.units(stroke.points_mm.front()));
    out.pairs("PD", std::vector<Point2>(stroke.points_mm.begin() + 1, stroke.points_mm.end()));
    out.command("PU");
  }
  if (stroke_offsets) stroke_offsets->push_back(out.size());
  out.command("PU0,0");
  out.command("SP0");
  return out.text();
}

}  // namespace lastcut
