// DXF written by lastcut (cut files and molds), read back by dxf-parser under node (a reader nobody
// on the project wrote): the geometry a CAD program or a cutter's import would see.
#include <gtest/gtest.h>

#include "engine/mold/mold_dxf.hpp"
#include "engine/toolpath/dxf_writer.hpp"
#include "interpreters.hpp"
#include "test_layouts.hpp"

namespace lastcut::test {
namespace {

constexpr double kTolerance_mm = 1e-5;

std::string cut_file_dxf(const CutProgram& program, const MachineProfile&) { return write_dxf(program); }

bool same_point(const Point2& a, const Point2& b) { return (a - b).norm() < kTolerance_mm; }

TEST(ToolpathDxfRoundTrip, EveryOutlineIsOneClosedCutPolylineAndEveryMarkALine) {
  const ShoeJob job = write_shoe_job("grbl-drag-knife", "dxf-roundtrip", "job.dxf", cut_file_dxf);
  const ParsedDxf dxf = dxf_via_node(job.file);
  EXPECT_EQ(dxf.acadver, "AC1015");
  EXPECT_EQ(dxf.insunits, 4);  // millimetres
  EXPECT_EQ(dxf.layers, (std::vector<std::string>{"0", "CUT", "MARK", "TEXT"}));
  for (const Placement& placement : job.layout.placements) {
    const NestItem& item = find_item(job.instance, placement.item);
    const Polygon2 outline = expected_outline(item, placement);
    int outlines = 0;
    for (const ParsedDxfEntity& entity : dxf.entities) {
      if (entity.layer != "CUT" || entity.points_mm.size() != outline.points.size()) continue;
      bool all = entity.closed && entity.type == "LWPOLYLINE";
      for (const Point2& vertex : outline.points) all = all && distance_to_polyline(vertex, entity.points_mm) < kTolerance_mm;
      outlines += all;
    }
    EXPECT_EQ(outlines, 1) << "item " << placement.item;
    for (const ItemMark& mark : item.marks) {
      const Point2 from = expected_point(mark.from_mm, placement), to = expected_point(mark.to_mm, placement);
      int lines = 0;
      for (const ParsedDxfEntity& entity : dxf.entities)
        lines += entity.layer == "MARK" && entity.type == "LINE" && entity.points_mm.size() == 2 &&
                 ((same_point(entity.points_mm[0], from) && same_point(entity.points_mm[1], to)) ||
                  (same_point(entity.points_mm[0], to) && same_point(entity.points_mm[1], from)));
      EXPECT_EQ(lines, 1) << "mark " << mark.name << " of item " << placement.item;
    }
  }
}

TEST(ToolpathDxfRoundTrip, AMoldReadsAsItsOutlineLabelAndNamedNotches) {
  Mold mold{"m-42-left medial", Polygon2{{{0, 0}, {180, 0}, {200, 60}, {170, 110}, {20, 100}}}, {}};
  mold.marks.push_back({"heel", Point2(0, 0) * 0.5 + Point2(20, 100) * 0.5, Point2(1, -0.1).normalized()});
  mold.marks.push_back({"toe", Point2(200, 60), Point2(-1, 0)});
  const auto file = scratch_dir("dxf-mold") / "medial.dxf";
  write_mold_dxf(file, mold);
  const ParsedDxf dxf = dxf_via_node(file);
  int outlines = 0, notches = 0;
  std::vector<std::string> texts;
  for (const ParsedDxfEntity& entity : dxf.entities) {
    if (entity.layer == "CUT" && entity.closed && entity.points_mm.size() == mold.outline.points.size()) {
      bool all = true;
      for (size_t k = 0; k < mold.outline.points.size(); ++k) all = all && same_point(entity.points_mm[k], mold.outline.points[k]);
      outlines += all;
    }
    if (entity.layer == "MARK" && entity.type == "LINE") ++notches;
    if (entity.type == "TEXT") texts.push_back(entity.text);
  }
  EXPECT_EQ(outlines, 1);
  EXPECT_EQ(notches, 2);
  EXPECT_NE(std::find(texts.begin(), texts.end(), "m-42-left medial"), texts.end());
  EXPECT_NE(std::find(texts.begin(), texts.end(), "heel"), texts.end());
  EXPECT_NE(std::find(texts.begin(), texts.end(), "toe"), texts.end());
  EXPECT_EQ(dxf.insunits, 4);
}

}  // namespace
}  // namespace lastcut::test
