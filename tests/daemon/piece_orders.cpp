#include "tests/daemon/piece_orders.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>

#include <polyclipping/clipper.hpp>

#include "engine/core/dxf_document.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/pattern/aama_dxf.hpp"
#include "tests/daemon/daemon_harness.hpp"
#include "tests/daemon/daemon_rig.hpp"
#include "tests/daemon/gcode_pieces.hpp"

namespace lastcut::daemon::testing {
namespace {

std::vector<Point2> box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// An upper's tongue of leather and its linings, from the roll: one pattern set of two materials, cut in
// two parts (the linings on the roll, then the tongues on a hide); grain along each piece.
std::vector<PatternPiece> tongue_and_linings() {
  PatternPiece vamp;
  vamp.name = "lining vamp";
  vamp.size = "41";
  vamp.category = "lining";
  vamp.annotation = "right";
  vamp.quantity = 1;
  vamp.cut_line_mm = {{0, 0}, {240, 10}, {260, 80}, {200, 150}, {40, 140}, {0, 70}};
  vamp.notches = {{{120, 5}, Point2(0, 1)}};
  vamp.grain_line_mm = std::array<Point2, 2>{Point2(40, 70), Point2(200, 70)};
  PatternPiece quarter = vamp;
  quarter.name = "quarter lining";
  quarter.quantity = 2;
  quarter.cut_line_mm = {{0, 0}, {220, 0}, {230, 60}, {180, 110}, {0, 100}};
  quarter.notches = {{{100, 0}, Point2(0, 1)}};
  quarter.grain_line_mm = std::array<Point2, 2>{Point2(20, 50), Point2(180, 50)};
  PatternPiece tongue = vamp;
  tongue.name = "tongue";
  tongue.category = "leather";
  tongue.quantity = 1;
  tongue.cut_line_mm = {{0, 0}, {60, -5}, {70, 150}, {40, 170}, {0, 150}};
  tongue.notches = {{{35, -3}, Point2(0, 1)}};
  tongue.grain_line_mm = std::array<Point2, 2>{Point2(35, 20), Point2(35, 140)};
  return {vamp, quarter, tongue};
}

ClipperLib::Path to_path(const std::vector<Point2>& points) {
  ClipperLib::Path path;
  for (const Point2& p : points) path.emplace_back(std::llround(p.x() * 1000), std::llround(p.y() * 1000));
  return path;
}

double overlap_mm2(const Polygon2& shrunk_piece, const Polygon2& zone) {
  ClipperLib::Clipper clipper;
  clipper.AddPath(to_path(shrunk_piece.points), ClipperLib::ptSubject, true);
  clipper.AddPath(to_path(zone.points), ClipperLib::ptClip, true);
  ClipperLib::Paths common;
  clipper.Execute(ClipperLib::ctIntersection, common, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  double area = 0;
  for (const auto& part : common) area += std::abs(ClipperLib::Area(part)) * 1e-6;
  return area;
}

// The piece 1 mm inside its cut (the knife's trail and the drawing's rounding stay outside the judgement).
Polygon2 shrunk(const Polygon2& ring) {
  ClipperLib::ClipperOffset offset;
  offset.AddPath(to_path(ring.points), ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
  ClipperLib::Paths inner;
  offset.Execute(inner, -1000);
  Polygon2 result;
  if (!inner.empty())
    for (const auto& p : inner.front()) result.points.emplace_back(p.X * 1e-3, p.Y * 1e-3);
  return result;
}

// The pieces tongue_and_linings() cuts from the lining roll.
bool is_lining(const std::string& label) { return label.find("lining") != std::string::npos; }

double axis_gap_deg(double a_deg, double b_deg) {
  double gap = std::fmod(std::abs(a_deg - b_deg), 180.0);
  return std::min(gap, 180 - gap);
}

}  // namespace

std::vector<PieceOrder> write_piece_orders(const std::filesystem::path& staging) {
  std::filesystem::create_directories(staging);
  std::vector<PieceOrder> orders = {
      {"derby-201.stl", "order = \"201\"\nstyle = \"derby\"\nside = \"pair\"\nsize = \"40\"\nmaterial = \"leather\"\n", "201"},
      // The lined derby: its linings are of material lining, cut from the roll before its leather (two parts).
      {"derby-202.stl", "order = \"202\"\nstyle = \"derby-lined\"\nside = \"pair\"\nsize = \"44\"\nmaterial = \"leather\"\n", "202"},
      {"loafer-203.stl", "order = \"203\"\nstyle = \"loafer\"\nside = \"pair\"\nsize = \"38\"\nmaterial = \"leather\"\n", "203"},
      // The materials from the pieces' Category: the tongues of leather (hides, cutter-1), the linings of
      // the lining roll (on cutter-2, the material's cutter).
      {"tongue-301.dxf", "order = \"301\"\nside = \"pair\"\n", "301"}};
  write_variant(small_last(40, "right", 7), staging / orders[0].file, orders[0].file);
  write_variant(small_last(44, "left", 7), staging / orders[1].file, orders[1].file);
  write_variant(small_last(38, "right", 7), staging / orders[2].file, orders[2].file);
  write_aama_dxf(staging / orders[3].file, tongue_and_linings());
  return orders;
}

std::string piece_paths_config() {
  return "hides = \"hides\"\nstyles = \"" + (std::filesystem::path(LASTCUT_SOURCE_DIR) / "config" / "styles").string() + "\"\n";
}

std::string piece_materials_config(const std::string& hide_cutter) {
  // The leather's own rules are looser than the styles' (vamp 10 deg and grade 3, the others 20 and 2):
  // the pieces' rules must win.
  return "[materials.leather]\nkind = \"hide\"\ncutter = \"" + hide_cutter + "\"\npairs = \"same_hide\"\n"
         "min_quality = 1\ngrain_tolerance_deg = 45\nspacing_mm = 3\nrotation_step_deg = 90\n"
         "[materials.lining]\ncutter = \"cutter-2\"\nwidth_mm = 800\nlength_mm = 1200\nspacing_mm = 2\nrotation_step_deg = 90\n";
}

std::vector<QualityZone> zoned_hide_zones(double w_mm, double h_mm) {
  return {{Polygon2{box(0, 0, 0.3 * w_mm, 0.25 * h_mm)}, 1}, {Polygon2{box(0.55 * w_mm, 0.7 * h_mm, w_mm, h_mm)}, 2}};
}

void write_zoned_hide(const std::filesystem::path& file, double w_mm, double h_mm) {
  DxfDocument dxf(DxfVersion::R12, {{"HIDE", 7}, {"ZONE_1", 3}, {"ZONE_2", 4}, {"BACKBONE", 5}});
  dxf.polyline("HIDE", box(0, 0, w_mm, h_mm), true);
  for (const QualityZone& zone : zoned_hide_zones(w_mm, h_mm))
    dxf.polyline("ZONE_" + std::to_string(zone.quality), zone.shape.points, true);
  dxf.polyline("BACKBONE", {{10, h_mm / 2}, {w_mm - 10, h_mm / 2}}, false);
  write_text(file, dxf.str());
}

std::vector<std::filesystem::path> job_items_files(const std::filesystem::path& job_dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(job_dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() == ".json" && (name == "items.json" || name.rfind("items-", 0) == 0)) files.push_back(entry.path());
  }
  return files;
}

std::map<std::string, NestItem> items_by_label(const std::vector<std::filesystem::path>& items_files) {
  std::map<std::string, NestItem> items;
  for (const auto& file : items_files)
    for (const NestItem& item : items_from_json(read_json_file(file), file.string())) items[item.label] = item;
  return items;
}

void check_cut_file(const std::string& gcode, const std::string& batch, const std::vector<QualityZone>& zones,
                    const std::map<std::string, NestItem>& items, CutPieces& cut) {
  for (const CutPiece& piece : pieces_of_gcode(gcode)) {
    ++cut.times_cut[piece.label];
    cut.hide_of[piece.label] = zones.empty() ? "" : batch;
    const auto item = items.find(piece.label);
    if (item == items.end()) {
      cut.problems.push_back(batch + ": a piece no job has: \"" + piece.label + "\"");
      continue;
    }
    const Polygon2 outline = cut_outline(piece);
    const double area = std::abs(signed_area(outline)), own = std::abs(signed_area(item->second.shape));
    if (std::abs(area - own) > 0.02 * own) {
      cut.problems.push_back(batch + ": \"" + piece.label + "\" cut with " + std::to_string(area) + " mm2, its item has " + std::to_string(own));
      continue;
    }
    if (zones.empty()) continue;
    const Polygon2 inner = shrunk(outline);
    for (const QualityZone& zone : zones) {
      if (zone.quality >= item->second.min_quality) continue;
      ++cut.zone_checks;
      if (const double overlap = overlap_mm2(inner, zone.shape); overlap > 1)
        cut.problems.push_back(batch + ": \"" + piece.label + "\" lies " + std::to_string(overlap) + " mm2 on ZONE_" +
                               std::to_string(zone.quality) + " (needs grade " + std::to_string(item->second.min_quality) + ")");
    }
    if (!item->second.grain_deg) continue;
    // The cut turned the piece by the angle between the two principal axes; the grain turned with it.
    const double turned_deg = principal_axis_deg(outline) - principal_axis_deg(item->second.shape);
    const double off_deg = axis_gap_deg(*item->second.grain_deg + turned_deg, 0);  // the backbone runs along x
    ++cut.grain_checks;
    if (off_deg > item->second.grain_tolerance_deg + 1.5)
      cut.problems.push_back(batch + ": \"" + piece.label + "\" has its grain " + std::to_string(off_deg) +
                             " deg off the backbone (tolerance " + std::to_string(item->second.grain_tolerance_deg) + ")");
  }
}

int expect_every_order_cut_once(const std::vector<PieceOrder>& orders, const std::map<std::string, NestItem>& items,
                                CutPieces& cut) {
  for (const std::string& problem : cut.problems) ADD_FAILURE() << problem;
  int pieces = 0;
  for (const auto& [label, item] : items) {
    pieces += item.demand;
    EXPECT_EQ(cut.times_cut[label], item.demand) << label;
  }
  // A derby pair (4 pieces a foot), a lined derby pair (4, its tongue and 3 linings a foot), a loafer pair
  // (5 a foot), the pattern set's tongue and its linings (1 + 3 a foot).
  EXPECT_EQ(pieces, 8 + 16 + 10 + 2 + 6);
  // Each order's leather on one hide (a pair from one hide), its linings on the roll.
  for (const PieceOrder& order : orders) {
    std::set<std::string> hides, rolls;
    for (const auto& [label, item] : items) {
      if (label.rfind("#" + order.order + " ", 0) != 0) continue;
      (is_lining(label) ? rolls : hides).insert(cut.hide_of[label]);
    }
    EXPECT_EQ(hides.size(), 1u) << order.order;
    EXPECT_FALSE(hides.empty() || hides.begin()->empty()) << order.order << ": its leather is not on a hide";
    EXPECT_EQ(rolls.size(), order.order == "301" || order.order == "202" ? 1u : 0u) << order.order;
    if (!rolls.empty()) {
      EXPECT_EQ(*rolls.begin(), "") << order.order << ": its linings are not on the roll";
    }
  }
  int zone_checks = 0, grain_checks = 0;
  for (const auto& [label, item] : items) {
    if (is_lining(label)) continue;
    for (const QualityZone& zone : zoned_hide_zones(kPieceHideWidth_mm, kPieceHideHeight_mm))
      zone_checks += item.demand * (zone.quality < item.min_quality);
    grain_checks += item.demand * item.grain_deg.has_value();
  }
  EXPECT_EQ(cut.zone_checks, zone_checks);
  EXPECT_EQ(cut.grain_checks, grain_checks);
  EXPECT_EQ(grain_checks, 30);  // every leather piece has a grain line
  std::printf("%d pieces cut, %d zone checks, %d grain checks\n", pieces, cut.zone_checks, cut.grain_checks);
  return pieces;
}

}  // namespace lastcut::daemon::testing
