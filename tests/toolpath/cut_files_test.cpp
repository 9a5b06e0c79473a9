// DXF and SVG files: structure a CAD program needs, true geometry, the three layers.
#include <gtest/gtest.h>

#include <map>

#include "engine/toolpath/cut_file.hpp"
#include "engine/toolpath/layout_pieces.hpp"
#include "engine/toolpath/plan_cut_program.hpp"
#include "interpreters.hpp"
#include "test_layouts.hpp"

namespace lastcut::test {
namespace {

struct DxfPair {
  int code;
  std::string value;
};

std::vector<DxfPair> read_pairs(const std::string& text) {
  std::vector<DxfPair> pairs;
  std::istringstream in(text);
  std::string code, value;
  while (std::getline(in, code) && std::getline(in, value)) pairs.push_back({std::stoi(code), value});
  return pairs;
}

// Entities of the ENTITIES section: type, layer, points (10/20), flags (70).
struct DxfEntity {
  std::string type, layer;
  std::vector<Point2> points;
  int flags = 0;
};

std::vector<DxfEntity> entities_of(const std::vector<DxfPair>& pairs) {
  std::vector<DxfEntity> entities;
  bool in_entities = false;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const DxfPair& pair = pairs[i];
    if (pair.code == 2 && pair.value == "ENTITIES") in_entities = true;
    if (!in_entities) continue;
    if (pair.code == 0) {
      if (pair.value == "ENDSEC") break;
      entities.push_back({pair.value, "", {}, 0});
    } else if (!entities.empty()) {
      DxfEntity& entity = entities.back();
      if (pair.code == 8) entity.layer = pair.value;
      if (pair.code == 70) entity.flags = std::stoi(pair.value);
      if (pair.code == 10 || pair.code == 11) entity.points.push_back(Point2(std::stod(pair.value), 0));
      if (pair.code == 20 || pair.code == 21) entity.points.back().y() = std::stod(pair.value);
    }
  }
  return entities;
}

TEST(ToolpathDxfFile, HeaderTablesLayersAndTrueGeometry) {
  const NestInstance instance = shoe_instance();
  const Layout layout = shoe_layout();
  const MachineProfile profile = profile_named("grbl-drag-knife");
  const CutProgram program = plan_cut_program(placed_pieces(layout, instance, SheetRef{}), profile);
  const std::string text = write_cut_file(program, profile, CutFileFormat::Dxf);
  const std::vector<DxfPair> pairs = read_pairs(text);
  ASSERT_GT(pairs.size(), 100u);
  EXPECT_EQ(pairs.back().code, 0);
  EXPECT_EQ(pairs.back().value, "EOF");
  std::vector<std::string> sections;
  std::map<std::string, std::string> header;
  std::vector<std::string> layers;
  for (size_t i = 0; i + 1 < pairs.size(); ++i) {
    if (pairs[i].code == 0 && pairs[i].value == "SECTION") sections.push_back(pairs[i + 1].value);
    if (pairs[i].code == 9) header[pairs[i].value] = pairs[i + 1].value;
    if (pairs[i].code == 0 && pairs[i].value == "LAYER") {
      for (size_t j = i + 1; j < pairs.size() && pairs[j].code != 0; ++j) {
        if (pairs[j].code == 2) layers.push_back(pairs[j].value);
      }
    }
  }
  EXPECT_EQ(sections, (std::vector<std::string>{"HEADER", "TABLES", "BLOCKS", "ENTITIES"}));
  EXPECT_EQ(header["$ACADVER"], "AC1015");
  EXPECT_EQ(header["$INSUNITS"], "4");
  EXPECT_EQ(layers, (std::vector<std::string>{"0", "CUT", "MARK", "TEXT"}));

  const std::vector<DxfEntity> entities = entities_of(pairs);
  int cut = 0, mark = 0, text_strokes = 0;
  for (const DxfEntity& entity : entities) {
    if (entity.layer == "CUT") {
      ++cut;
      EXPECT_EQ(entity.type, "LWPOLYLINE");
      EXPECT_EQ(entity.flags & 1, 1) << "closed";
    }
    if (entity.layer == "MARK") {
      ++mark;
      EXPECT_EQ(entity.type, "LINE");
    }
    if (entity.layer == "TEXT") ++text_strokes;
  }
  EXPECT_EQ(cut, static_cast<int>(layout.placements.size()));
  size_t expected_marks = 0;
  for (const Placement& placement : layout.placements) expected_marks += find_item(instance, placement.item).marks.size();
  EXPECT_EQ(mark, static_cast<int>(expected_marks));
  EXPECT_GT(text_strokes, 20);
  // Every placed outline is one CUT polyline with the layout's vertices (not the holder path).
  for (const Placement& placement : layout.placements) {
    const Polygon2 outline = expected_outline(find_item(instance, placement.item), placement);
    int matching = 0;
    for (const DxfEntity& entity : entities) {
      if (entity.layer != "CUT" || entity.points.size() != outline.points.size()) continue;
      bool all = true;
      for (const Point2& vertex : outline.points) all = all && distance_to_polyline(vertex, entity.points) < 1e-5;
      matching += all;
    }
    EXPECT_EQ(matching, 1) << "item " << placement.item;
  }
}

TEST(ToolpathSvgFile, WellFormedWithOnePathPerPiece) {
  const NestInstance instance = shoe_instance();
  const Layout layout = shoe_layout();
  const MachineProfile profile = profile_named("grbl-tangential-knife");
  const CutProgram program = plan_cut_program(placed_pieces(layout, instance, SheetRef{}), profile);
  const auto file = scratch_dir("svg") / "preview.svg";
  save_cut_file(file, write_cut_file(program, profile, CutFileFormat::Svg));
  // An independent XML parser (python3's minidom) reads it and counts the cut outlines.
  const std::string count = run_command(
      "python3 -c \"import sys, xml.dom.minidom as m; d = m.parse(sys.argv[1]); "
      "g = [e for e in d.getElementsByTagName('g') if e.getAttribute('id') == 'cut'][0]; "
      "print(len(g.getElementsByTagName('path')))\" '" + file.string() + "'");
  EXPECT_EQ(std::stoi(count), static_cast<int>(layout.placements.size()));
  EXPECT_FALSE(std::filesystem::exists(file.string() + ".partial"));
}

}  // namespace
}  // namespace lastcut::test
