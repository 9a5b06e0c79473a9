#include "tests/daemon/hide_samples.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/core/dxf_document.hpp"
#include "engine/nest/layout_check.hpp"
#include "engine/nest/nest_json.hpp"
#include "tests/daemon/daemon_harness.hpp"

namespace lastcut::daemon::testing {
namespace {

std::vector<Point2> rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

}  // namespace

std::string leather_hide_material(const std::string& cutter) {
  return "[materials.leather]\nkind = \"hide\"\ncutter = \"" + cutter + "\"\npairs = \"same_hide\"\n"
         "min_quality = 2\ntoe_min_quality = 3\ngrain_tolerance_deg = 10\nspacing_mm = 3\nrotation_step_deg = 90\n";
}

void write_hide_dxf(const std::filesystem::path& file, double w, double h, bool zones) {
  DxfDocument dxf(DxfVersion::R12, {{"HIDE", 7}, {"HOLE", 1}, {"ZONE_1", 3}, {"ZONE_2", 4}, {"BACKBONE", 5}});
  dxf.polyline("HIDE", rectangle(0, 0, w, h), true);
  dxf.polyline("HOLE", rectangle(w - 45, h / 2 - 10, w - 25, h / 2 + 10), true);
  if (zones) {
    dxf.polyline("ZONE_1", rectangle(w - 60, 10, w - 20, 50), true);
    dxf.polyline("ZONE_2", rectangle(w - 60, h - 50, w - 20, h - 10), true);
    dxf.polyline("BACKBONE", {{10, h / 2}, {w - 10, h / 2}}, false);
  }
  write_text(file, dxf.str());
}

void write_hide_json(const std::filesystem::path& file, double w, double h) {
  nlohmann::json outer = nlohmann::json::array(), hole = nlohmann::json::array();
  for (const Point2& p : rectangle(0, 0, w, h)) outer.push_back({p.x(), p.y()});
  for (const Point2& p : rectangle(w - 20, h / 2 - 6, w - 8, h / 2 + 6)) hole.push_back({p.x(), p.y()});
  nlohmann::json bin;
  bin["id"] = 0;
  bin["shape"]["type"] = "polygon";
  bin["shape"]["data"]["outer"] = outer;
  bin["shape"]["data"]["inner"] = nlohmann::json::array({hole});
  write_text(file, nlohmann::json{{"bins", nlohmann::json::array({bin})}}.dump());
}

std::pair<double, double> piece_box_mm(const std::filesystem::path& items_json) {
  double length = 0, width = 0;
  for (const NestItem& item : items_from_json(read_json_file(items_json), "job")) {
    Point2 low = item.shape.points[0], high = low;
    for (const Point2& p : item.shape.points) low = low.cwiseMin(p), high = high.cwiseMax(p);
    length = std::max(length, std::max(high.x() - low.x(), high.y() - low.y()));
    width = std::max(width, std::min(high.x() - low.x(), high.y() - low.y()));
  }
  return {length, width};
}

double pieces_area_mm2(const std::filesystem::path& items_json) {
  double area = 0;
  for (const NestItem& item : items_from_json(read_json_file(items_json), "job"))
    area += item.demand * std::abs(signed_area(item.shape));
  return area;
}

std::map<std::string, int> pieces_by_label(const std::filesystem::path& items_json) {
  std::map<std::string, int> pieces;
  for (const NestItem& item : items_from_json(read_json_file(items_json), items_json.string())) pieces[item.label] += item.demand;
  return pieces;
}

std::map<std::string, int> placed_by_label(const std::filesystem::path& layout_json) {
  const nlohmann::json json = read_json_file(layout_json);
  std::map<int, std::string> label_of;
  for (const NestItem& item : instance_from_layout_json(json).items) label_of[item.id] = item.label;
  std::map<std::string, int> placed;
  for (const Placement& p : layout_from_json(json).placements) ++placed[label_of.at(p.item)];
  return placed;
}

nlohmann::json spool_hide_batch(const std::filesystem::path& spool, const std::string& file) {
  std::error_code error;
  for (std::filesystem::directory_iterator it(spool / "batches", error), end; !error && it != end; it.increment(error)) {
    auto batch = nlohmann::json::parse(read_text(it->path() / "batch.json"), nullptr, false);
    if (!batch.is_discarded() && batch.contains("hide") && batch["hide"].value("file", "") == file) return batch;
  }
  return nullptr;
}

std::string spool_hide_stage(const std::filesystem::path& spool, const std::string& file) {
  const auto batch = spool_hide_batch(spool, file);
  return batch.is_null() ? "" : batch.value("stage", "");
}

std::set<std::string> check_orders_over_hides(const std::map<std::string, std::filesystem::path>& layouts,
                                              const std::map<std::string, int>& split,
                                              const std::map<std::string, int>& whole, const std::string& first_hide) {
  std::map<std::string, int> cut;
  std::set<std::string> hides_of_split, hides_of_whole;
  for (const auto& [hide, layout] : layouts) {
    check_hide_layout(layout, 0);
    for (const auto& [label, copies] : placed_by_label(layout)) {
      cut[label] += copies;
      (split.count(label) ? hides_of_split : hides_of_whole).insert(hide);
    }
  }
  std::map<std::string, int> expected = split;
  expected.insert(whole.begin(), whole.end());
  EXPECT_EQ(cut, expected) << "every piece of both orders cut exactly once";
  EXPECT_EQ(hides_of_whole.size(), 1u) << "an order that may not split lies on one hide";
  EXPECT_GE(hides_of_split.size(), 2u);
  EXPECT_EQ(hides_of_split.count(first_hide), 1u);
  return hides_of_split;
}

std::size_t check_hide_layout(const std::filesystem::path& layout_json, std::size_t zones) {
  const auto json = read_json_file(layout_json);
  const NestInstance instance = instance_from_layout_json(json);
  const Layout layout = layout_from_json(json);
  const auto problems = check_layout(layout, instance);
  EXPECT_TRUE(problems.empty()) << layout_json << ": " << problems.front();
  EXPECT_EQ(instance.bins.size(), 1u);
  if (instance.bins.empty()) return 0;
  const bool backbone = instance.bins[0].backbone_deg.has_value();
  for (const NestItem& item : instance.items) {
    EXPECT_EQ(item.min_quality, 2) << "the material's min_quality";
    // Grain only where the hide has a backbone; the checker measures it against the backbone.
    EXPECT_EQ(item.grain_deg.has_value(), backbone);
    if (backbone) {
      EXPECT_EQ(item.grain_tolerance_deg, 10);
    }
    EXPECT_EQ(item.quality_regions.size(), 1u) << "the toe region of every mold";
    if (!item.quality_regions.empty()) {
      EXPECT_EQ(item.quality_regions[0].min_quality, 3) << "the material's toe_min_quality";
    }
  }
  EXPECT_EQ(instance.bins[0].zones.size(), zones) << "the low-grade zones are checked";
  EXPECT_EQ(instance.bins[0].holes.size(), 1u) << "the hole is checked";
  return layout.placements.size();
}

}  // namespace lastcut::daemon::testing
