// HPGL written by lastcut, read back by hp2xx (an HPGL interpreter nobody on the project wrote).
#include <gtest/gtest.h>

#include <regex>

#include "engine/toolpath/drag_knife.hpp"
#include "engine/toolpath/hpgl_writer.hpp"
#include "engine/toolpath/layout_pieces.hpp"
#include "engine/toolpath/plan_cut_program.hpp"
#include "interpreters.hpp"
#include "test_layouts.hpp"

namespace lastcut::test {
namespace {

constexpr double kTolerance_mm = 0.025;

ShoeJob write_job(const std::string& profile_name, const std::string& test_name) {
  return write_shoe_job(profile_name, test_name, "job.plt", write_hpgl);
}

TEST(ToolpathHpglRoundTrip, EveryOutlineIsOneClosedPathAndMarksLandWhereTheLayoutPutsThem) {
  const ShoeJob job = write_job("hpgl-pen-plotter", "pen");
  const std::vector<InterpretedPath> paths = hpgl_paths_via_hp2xx(job.file, 40.0);
  EXPECT_EQ(paths.size(), job.program.strokes.size()) << "every pen-down run of the program, no more";
  for (const Placement& placement : job.layout.placements) {
    const Polygon2 outline = expected_outline(find_item(job.instance, placement.item), placement);
    int tracing = 0;
    for (const InterpretedPath& path : paths) tracing += traces_outline(path.points_mm, outline, kTolerance_mm);
    EXPECT_EQ(tracing, 1) << "item " << placement.item << " at (" << placement.x << ", " << placement.y << ")";
    for (const ItemMark& mark : find_item(job.instance, placement.item).marks) {
      const Point2 from = expected_point(mark.from_mm, placement), to = expected_point(mark.to_mm, placement);
      int found = 0;
      for (const InterpretedPath& path : paths) {
        if (path.points_mm.size() != 2) continue;
        const Point2 a = path.points_mm[0], b = path.points_mm[1];
        found += ((a - from).norm() <= kTolerance_mm && (b - to).norm() <= kTolerance_mm) ||
                 ((a - to).norm() <= kTolerance_mm && (b - from).norm() <= kTolerance_mm);
      }
      EXPECT_EQ(found, 1) << "mark " << mark.name << " of item " << placement.item;
    }
  }
}

TEST(ToolpathHpglRoundTrip, DragKnifeBladeTipFollowsEveryOutline) {
  const ShoeJob job = write_job("hpgl-knife-cutter", "knife");
  const double blade_offset_mm = profile_named("hpgl-knife-cutter").cut.blade_offset_mm;
  const std::vector<InterpretedPath> paths = hpgl_paths_via_hp2xx(job.file, 40.0);
  for (const Placement& placement : job.layout.placements) {
    const Polygon2 outline = expected_outline(find_item(job.instance, placement.item), placement);
    int tracing = 0;
    for (const InterpretedPath& path : paths) {
      // The holder starts blade_offset_mm ahead of the tip, which waits on the start corner.
      const Point2 holder_start = path.points_mm.front();
      const Point2* tip_start = nullptr;
      for (const Point2& vertex : outline.points) {
        if (std::abs((vertex - holder_start).norm() - blade_offset_mm) <= kTolerance_mm) tip_start = &vertex;
      }
      if (!tip_start) continue;
      std::vector<Point2> tip = simulate_drag_knife_tip(path.points_mm, *tip_start, blade_offset_mm, 0.01);
      tip.insert(tip.begin(), *tip_start);
      tracing += traces_outline(tip, outline, kTolerance_mm);
    }
    EXPECT_EQ(tracing, 1) << "item " << placement.item << " at (" << placement.x << ", " << placement.y << ")";
  }
  // The holder itself is not on the outline: compensation really happened.
  int holder_on_outline = 0;
  for (const Placement& placement : job.layout.placements) {
    const Polygon2 outline = expected_outline(find_item(job.instance, placement.item), placement);
    for (const InterpretedPath& path : paths) holder_on_outline += traces_outline(path.points_mm, outline, kTolerance_mm);
  }
  EXPECT_EQ(holder_on_outline, 0);
}

TEST(ToolpathHpglRoundTrip, CommandsFitSmallInputBuffers) {
  const ShoeJob job = write_job("hpgl-knife-cutter", "buffers");
  const MachineProfile& profile = job.profile;
  const std::string text = read_text(job.file);
  EXPECT_EQ(text.rfind("IN;", 0), 0u);
  std::istringstream lines(text);
  std::string line;
  int pd_commands = 0;
  std::set<std::string> pens;
  while (std::getline(lines, line)) {
    EXPECT_LE(static_cast<int>(line.size()), profile.hpgl.max_line_length) << line;
    EXPECT_EQ(line.back(), ';') << line;
    if (line.rfind("PD", 0) == 0) {
      ++pd_commands;
      const long commas = std::count(line.begin(), line.end(), ',');
      EXPECT_LE((commas + 1) / 2, profile.hpgl.max_points_per_command) << line;
    }
    if (line.rfind("SP", 0) == 0) pens.insert(line);
  }
  EXPECT_GT(pd_commands, static_cast<int>(job.program.strokes.size())) << "long runs were split";
  EXPECT_TRUE(pens.count("SP1;") && pens.count("SP2;")) << "knife and pen both selected";
  EXPECT_NE(text.find("VS3;"), std::string::npos) << "knife speed 30 mm/s = 3 cm/s";
}

}  // namespace
}  // namespace lastcut::test
