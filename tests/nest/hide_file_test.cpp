// Hide files (engine/nest/hide_file.hpp): the DXF layer convention, the JSON bin, the sidecar, and
// every refusal with its exact line. Geometry is checked against values computed here by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "engine/core/engine_error.hpp"
#include "engine/nest/hide_file.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

struct Ring {
  std::string layer;
  std::vector<Point2> points;
  bool closed = true;
};

// A minimal DXF (HEADER with $INSUNITS when >= 0, ENTITIES with LWPOLYLINEs and LINEs).
std::string dxf_text(int insunits, const std::vector<Ring>& rings, const std::vector<Ring>& lines = {}) {
  std::string text = "0\nSECTION\n2\nHEADER\n";
  if (insunits >= 0) text += "9\n$INSUNITS\n70\n" + std::to_string(insunits) + "\n";
  text += "0\nENDSEC\n0\nSECTION\n2\nENTITIES\n";
  for (const Ring& ring : rings) {
    text += "0\nLWPOLYLINE\n8\n" + ring.layer + "\n90\n" + std::to_string(ring.points.size()) + "\n70\n" +
            (ring.closed ? "1" : "0") + "\n";
    for (const Point2& p : ring.points) text += "10\n" + std::to_string(p.x()) + "\n20\n" + std::to_string(p.y()) + "\n";
  }
  for (const Ring& line : lines) {
    text += "0\nLINE\n8\n" + line.layer + "\n10\n" + std::to_string(line.points[0].x()) + "\n20\n" +
            std::to_string(line.points[0].y()) + "\n11\n" + std::to_string(line.points[1].x()) + "\n21\n" +
            std::to_string(line.points[1].y()) + "\n";
  }
  return text + "0\nENDSEC\n0\nEOF\n";
}

std::vector<Point2> rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

class HideFileTest : public ::testing::Test {
 protected:
  std::filesystem::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  // The one line read_hide_file refuses `file` with.
  std::string refusal(const std::filesystem::path& file) {
    try {
      read_hide_file(file);
    } catch (const EngineError& error) {
      return error.what();
    }
    return "(accepted)";
  }
  const lastcut::test::TempDir dir_{std::string("hide-file-") + ::testing::UnitTest::GetInstance()->current_test_info()->name()};
};

TEST_F(HideFileTest, DxfLayersGiveOutlineHolesZonesAndBackboneInMillimetres) {
  // In cm: a 100 x 60 cm hide, a 4 x 3 cm hole, a grade-1 zone of 20 x 10 cm, backbone at 30 deg.
  const double c30 = std::cos(M_PI / 6), s30 = std::sin(M_PI / 6);
  const auto file = write("calf-7.dxf", dxf_text(5,
                                                 {{"HIDE", rectangle(0, 0, 100, 60)},
                                                  {"HOLE", rectangle(10, 10, 14, 13)},
                                                  {"ZONE_1", rectangle(70, 40, 90, 50)},
                                                  {"OTHER", rectangle(-500, -500, 500, 500)}},
                                                 {{"BACKBONE", {{20, 20}, {20 + 10 * c30, 20 + 10 * s30}}}}));
  const HideFile hide = read_hide_file(file);
  EXPECT_EQ(hide.hide_id, "calf-7");
  EXPECT_EQ(hide.bin.name, "calf-7");
  EXPECT_NEAR(hide.area_m2, 1.0 * 0.6, 1e-12);
  EXPECT_NEAR(hide.usable_area_m2, 0.6 - 0.04 * 0.03, 1e-12);
  ASSERT_EQ(hide.bin.outer.points.size(), 4u);
  EXPECT_NEAR(hide.bin.outer.points[2].x(), 1000.0, 1e-9);
  EXPECT_NEAR(hide.bin.outer.points[2].y(), 600.0, 1e-9);
  ASSERT_EQ(hide.bin.holes.size(), 1u);
  EXPECT_NEAR(std::abs(signed_area(hide.bin.holes[0])), 40.0 * 30.0, 1e-6);
  ASSERT_EQ(hide.bin.zones.size(), 1u);
  EXPECT_EQ(hide.bin.zones[0].quality, 1);
  EXPECT_NEAR(signed_area(hide.bin.zones[0].shape), 200.0 * 100.0, 1e-6);
  ASSERT_TRUE(hide.bin.backbone_deg.has_value());
  EXPECT_NEAR(*hide.bin.backbone_deg, 30.0, 1e-4);  // the DXF's 6 decimals
  ASSERT_TRUE(hide.bin.backbone_point.has_value());  // the line's middle, in mm: pairs are mirrored about it
  EXPECT_NEAR(hide.bin.backbone_point->x(), 200 + 50 * c30, 1e-3);
  EXPECT_NEAR(hide.bin.backbone_point->y(), 200 + 50 * s30, 1e-3);
  EXPECT_TRUE(hide.material.empty());
  EXPECT_FALSE(hide.thickness_mm.has_value());
}

TEST_F(HideFileTest, ClockwiseRingsAreMadeCounterClockwiseAndBulgesFlattened) {
  // Outline clockwise, in mm without $INSUNITS, one edge a half circle (bulge 1) of radius 300 mm.
  std::string text = dxf_text(-1, {{"HIDE", {{0, 0}, {0, 600}, {800, 600}, {800, 0}}}});
  // Bulge on the vertex (0, 600) -> (800, 600): a half circle over the top edge, outward (clockwise turn).
  const std::string top = "10\n0.000000\n20\n600.000000\n";
  text.replace(text.find(top), top.size(), top + "42\n-1\n");
  const HideFile hide = read_hide_file(write("round.dxf", text));
  EXPECT_GT(signed_area(hide.bin.outer), 0.0);
  // Rectangle plus a half disc of radius 400 mm, within the flattening tolerance.
  EXPECT_NEAR(hide.area_m2, (800.0 * 600.0 + M_PI * 400.0 * 400.0 / 2) * 1e-6, 2e-4);
}

TEST_F(HideFileTest, JsonBinAndSidecar) {
  const auto file = write("h12.json", R"({"name": "ignored", "units": "cm", "bins": [{"id": 3, "stock": 1, "cost": 1,
    "shape": {"type": "polygon", "data": {"outer": [[0,0],[120,0],[120,80],[0,80],[0,0]],
                                          "inner": [[[10,10],[12,10],[12,12],[10,12]]]}},
    "zones": [{"quality": 2, "shape": {"type": "simple_polygon", "data": [[50,50],[60,50],[60,60],[50,60]]}}]}],
    "items": []})");
  write("h12.toml", "id = \"CALF-2026-0012\"\nmaterial = \"calf\"\ncutter = \"cutter-2\"\nthickness_mm = 1.4\n");
  const HideFile hide = read_hide_file(file);
  EXPECT_EQ(hide.hide_id, "CALF-2026-0012");
  EXPECT_EQ(hide.bin.name, "CALF-2026-0012");
  EXPECT_EQ(hide.bin.id, 0);
  EXPECT_EQ(hide.material, "calf");
  EXPECT_EQ(hide.cutter, "cutter-2");
  ASSERT_TRUE(hide.thickness_mm.has_value());
  EXPECT_DOUBLE_EQ(*hide.thickness_mm, 1.4);
  EXPECT_NEAR(hide.area_m2, 1.2 * 0.8, 1e-12);
  EXPECT_NEAR(hide.usable_area_m2, 0.96 - 0.02 * 0.02, 1e-12);
  ASSERT_EQ(hide.bin.zones.size(), 1u);
  EXPECT_EQ(hide.bin.zones[0].quality, 2);
  EXPECT_NEAR(hide.bin.zones[0].shape.points[1].x(), 600.0, 1e-9);
}

TEST_F(HideFileTest, EveryBaldacciHideScaledToMillimetresReads) {
  // The Baldacci hides are ~9000 x 8000 units (60 m^2 if mm: refused as implausible); scaled by
  // 0.25 by hand they are hides of 3-4.5 m^2 whose rings must all pass check_hide (some zones
  // overhang the outline by a sliver: accepted).
  const auto folder = std::filesystem::path(LASTCUT_SOURCE_DIR) / "../shared/data/nesting/leather";
  if (!std::filesystem::exists(folder)) GTEST_SKIP() << "no shared data at " << folder;
  int hides = 0;
  for (int n = 1; n <= 6; ++n) {
    std::ifstream in(folder / ("baldacci" + std::to_string(n) + ".json"));
    const nlohmann::json json = nlohmann::json::parse(in);
    for (nlohmann::json bin : json["bins"]) {
      const auto scale = [](nlohmann::json& ring) {
        for (auto& p : ring) p = {p[0].get<double>() * 0.25, p[1].get<double>() * 0.25};
      };
      double area_units = 0;  // shoelace on the original ring
      const auto& outer = bin["shape"]["data"]["outer"];
      for (size_t i = 0; i < outer.size(); ++i) {
        const auto& a = outer[i];
        const auto& b = outer[(i + 1) % outer.size()];
        area_units += a[0].get<double>() * b[1].get<double>() - b[0].get<double>() * a[1].get<double>();
      }
      scale(bin["shape"]["data"]["outer"]);
      for (auto& hole : bin["shape"]["data"]["inner"]) scale(hole);
      for (auto& zone : bin["zones"]) scale(zone["shape"]["data"]);
      const std::string name = "b" + std::to_string(n) + "-" + std::to_string(hides) + ".json";
      const HideFile hide = read_hide_file(write(name, bin.dump()));
      EXPECT_NEAR(hide.area_m2, std::abs(area_units) / 2 * 0.0625 * 1e-6, 1e-9) << name;
      EXPECT_EQ(hide.bin.holes.size(), bin["shape"]["data"]["inner"].size()) << name;
      EXPECT_EQ(hide.bin.zones.size(), bin["zones"].size()) << name;
      ++hides;
    }
  }
  EXPECT_GT(hides, 6);
}

TEST_F(HideFileTest, RefusalsAreOneLineEach) {
  const auto hide = [](std::vector<Ring> extra = {}) {
    std::vector<Ring> rings = {{"HIDE", rectangle(0, 0, 1000, 600)}};
    rings.insert(rings.end(), extra.begin(), extra.end());
    return rings;
  };
  std::filesystem::path f;
  f = write("open.dxf", dxf_text(4, {{"HIDE", rectangle(0, 0, 1000, 600), false}}));
  EXPECT_EQ(refusal(f), f.string() + ": the hide outline on layer HIDE is open; close it in the drawing program");
  f = write("none.dxf", dxf_text(4, {{"CUT", rectangle(0, 0, 1000, 600)}}));
  EXPECT_EQ(refusal(f), f.string() + ": no hide outline (a closed polyline on layer HIDE)");
  f = write("bowtie.dxf", dxf_text(4, {{"HIDE", {{0, 0}, {1000, 600}, {1000, 0}, {0, 600}}}}));
  EXPECT_EQ(refusal(f), f.string() + ": the hide outline crosses itself; redraw it as one simple closed line");
  f = write("hole-out.dxf", dxf_text(4, hide({{"HOLE", rectangle(950, 100, 1050, 200)}})));
  EXPECT_EQ(refusal(f), f.string() + ": the hole 1 reaches outside the hide outline (5000 mm^2 outside)");
  f = write("zone-out.dxf", dxf_text(4, hide({{"ZONE_1", rectangle(-100, -100, 100, 100)}})));
  EXPECT_EQ(refusal(f), f.string() + ": the zone 1 (grade 1) reaches outside the hide outline (30000 mm^2 outside)");
  f = write("zone-name.dxf", dxf_text(4, hide({{"ZONE_B", rectangle(100, 100, 200, 200)}})));
  EXPECT_EQ(refusal(f), f.string() + ": layer ZONE_B does not name a grade; zones go on ZONE_<whole number>");
  f = write("hole-open.dxf", dxf_text(4, hide({{"HOLE", rectangle(100, 100, 200, 200), false}})));
  EXPECT_EQ(refusal(f), f.string() + ": an open polyline on layer HOLE; close it in the drawing program");
  f = write("units.dxf", dxf_text(2, hide()));
  EXPECT_EQ(refusal(f), f.string() + ": drawing units $INSUNITS 2 are not supported; save the hide in mm, cm, m or inches");
  f = write("tiny.dxf", dxf_text(4, {{"HIDE", rectangle(0, 0, 200, 200)}}));
  EXPECT_EQ(refusal(f), f.string() + ": the hide outline encloses 0.04 m^2, outside 0.05..10 m^2; check the drawing's units");
  f = write("huge.dxf", dxf_text(6, {{"HIDE", rectangle(0, 0, 4, 3)}}));
  EXPECT_EQ(refusal(f), f.string() + ": the hide outline encloses 12 m^2, outside 0.05..10 m^2; check the drawing's units");
  f = write("two.dxf", dxf_text(4, {{"HIDE", rectangle(0, 0, 1000, 600)}, {"HIDE", rectangle(0, 0, 900, 600)}}));
  EXPECT_EQ(refusal(f), f.string() + ": 2 polylines on layer HIDE; a hide file holds one hide");
  f = write("text.dxf", "this is not\na drawing\n");
  EXPECT_EQ(refusal(f), f.string() + " is not a DXF file: line 1 is not a group code");
  f = write("cut.json", "{\"bins\": [");
  EXPECT_EQ(refusal(f), f.string() + " is not valid JSON (byte 11)");
  f = write("units.json", R"({"units": "furlong", "shape": [[0,0],[1000,0],[1000,600]]})");
  EXPECT_EQ(refusal(f), f.string() + ": units \"furlong\" are not supported; use mm, cm, m or in");
  // Found by tests/fuzz/hide_json_fuzz.cpp: "units" that is not text threw nlohmann's type_error past every caller.
  f = write("units-list.json", R"({"units": ["mm"], "shape": [[0,0],[1000,0],[1000,600]]})");
  EXPECT_EQ(refusal(f), f.string() + ": \"units\" must be text: mm, cm, m or in");
  // Found by tests/fuzz/hide_dxf_fuzz.cpp: a flag beyond int's range was converted with undefined behaviour.
  std::string flags = dxf_text(4, hide());
  flags.replace(flags.find("\n70\n1\n"), 6, "\n70\n99999999999\n");
  f = write("flags.dxf", flags);
  EXPECT_EQ(refusal(f), f.string() + ": '99999999999' is not a DXF integer (out of range)");
  // Found by tests/fuzz/hide_dxf_fuzz.cpp: a hole far from the origin overflowed Clipper's grid (its exception escaped).
  f = write("far.dxf", dxf_text(4, hide({{"HOLE", rectangle(1e16, 1e16, 1.1e16, 1.1e16)}})));
  EXPECT_EQ(refusal(f), f.string() + ": the hole 1 has a point more than 10 km from the drawing's origin; check the drawing's units");
  f = write("nobin.json", R"({"items": []})");
  EXPECT_EQ(refusal(f), f.string() + ": no hide outline (\"shape\" or \"outer\")");
  f = write("photo.png", "x");
  EXPECT_EQ(refusal(f), f.string() + ": not a hide file; expected .dxf or .json");
  EXPECT_EQ(refusal(dir_ / "missing.dxf"), "cannot read hide file " + (dir_ / "missing.dxf").string());
  // The sidecar: unknown keys and bad values.
  f = write("s1.dxf", dxf_text(4, hide()));
  write("s1.toml", "id = \"x\"\ncolour = \"red\"\n");
  EXPECT_EQ(refusal(f), (dir_ / "s1.toml").string() + ": unknown key \"colour\" (known: id, material, cutter, thickness_mm)");
  write("s1.toml", "thickness_mm = 45\n");
  EXPECT_EQ(refusal(f), (dir_ / "s1.toml").string() + ": thickness_mm must be a number of mm within 0.2..20");
  for (const std::string& line : {refusal(f)}) EXPECT_EQ(line.find('\n'), std::string::npos);
}

}  // namespace
}  // namespace lastcut
