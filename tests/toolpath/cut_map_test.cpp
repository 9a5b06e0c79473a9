// The cut map (cut-map.json): each piece's bytes in the cut file. Checked by reading the file
// back independently: every coordinate written inside a piece's byte span lies on that piece
// (within its placed outline's bounding box plus the knife's offset), the spans follow the
// cutting order without overlapping, and in G-code each span carries its own piece comment.
#include <gtest/gtest.h>

#include <regex>

#include "engine/toolpath/cut_map.hpp"
#include "engine/toolpath/gcode_writer.hpp"
#include "engine/toolpath/hpgl_writer.hpp"
#include "engine/toolpath/layout_pieces.hpp"
#include "engine/toolpath/plan_cut_program.hpp"
#include "test_layouts.hpp"

namespace lastcut::test {
namespace {

struct Box {
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  bool holds(const Point2& p, double margin) const {
    return p.x() >= x0 - margin && p.x() <= x1 + margin && p.y() >= y0 - margin && p.y() <= y1 + margin;
  }
};

Box box_of(const Polygon2& outline) {
  Box box;
  for (const Point2& p : outline.points) {
    box.x0 = std::min(box.x0, p.x()), box.y0 = std::min(box.y0, p.y());
    box.x1 = std::max(box.x1, p.x()), box.y1 = std::max(box.y1, p.y());
  }
  return box;
}

// Every X/Y pair of a G-code text, every PU/PD pair of an HPGL text (plotter units -> mm).
std::vector<Point2> coordinates(const std::string& text, bool hpgl, double units_per_mm) {
  std::vector<Point2> points;
  if (hpgl) {
    static const std::regex command("P[UD]([-0-9.,]+);");
    for (std::sregex_iterator it(text.begin(), text.end(), command), end; it != end; ++it) {
      std::vector<double> numbers;
      std::stringstream list((*it)[1].str());
      for (std::string number; std::getline(list, number, ',');) numbers.push_back(std::stod(number));
      for (std::size_t i = 0; i + 1 < numbers.size(); i += 2) points.emplace_back(numbers[i] / units_per_mm, numbers[i + 1] / units_per_mm);
    }
  } else {
    static const std::regex move("X(-?[0-9.]+) Y(-?[0-9.]+)");
    for (std::sregex_iterator it(text.begin(), text.end(), move), end; it != end; ++it)
      points.emplace_back(std::stod((*it)[1].str()), std::stod((*it)[2].str()));
  }
  return points;
}

void check_map(const std::string& profile_name, bool hpgl) {
  const NestInstance instance = shoe_instance();
  const Layout layout = shoe_layout();
  CutFile file;
  file.program = plan_cut_program(placed_pieces(layout, instance, SheetRef{}), profile_named(profile_name));
  const MachineProfile profile = profile_named(profile_name);
  file.text = hpgl ? write_hpgl(file.program, profile, &file.stroke_offsets)
                   : write_gcode(file.program, profile, &file.stroke_offsets);
  ASSERT_EQ(file.stroke_offsets.size(), file.program.strokes.size() + 1);
  EXPECT_EQ(file.text, hpgl ? write_hpgl(file.program, profile) : write_gcode(file.program, profile))
      << "recording the offsets changes no byte";
  const CutMap map = make_cut_map(file);
  ASSERT_EQ(map.pieces.size(), file.program.pieces.size());
  EXPECT_EQ(map.bytes_total, file.text.size());
  std::size_t previous_end = 0;
  for (std::size_t p = 0; p < map.pieces.size(); ++p) {
    const CutMapPiece& piece = map.pieces[p];
    ASSERT_LT(piece.first_byte, piece.end_byte) << "piece " << p;
    EXPECT_GE(piece.first_byte, previous_end) << "pieces are cut one after the other";
    previous_end = piece.end_byte;
    const std::string span = file.text.substr(piece.first_byte, piece.end_byte - piece.first_byte);
    const auto points = coordinates(span, hpgl, profile.hpgl.units_per_mm);
    ASSERT_FALSE(points.empty()) << "piece " << p;
    const Box box = box_of(piece.outline_mm);
    for (const Point2& point : points) {
      EXPECT_TRUE(box.holds(point, 3.0)) << profile_name << " piece " << p << " (" << piece.label << ") has ("
                                         << point.x() << ", " << point.y() << ") in its bytes";
    }
    if (!hpgl) {
      EXPECT_NE(span.find("piece " + std::to_string(p + 1) + "/"), std::string::npos) << span.substr(0, 200);
    }
  }
  const nlohmann::json json = to_json(map);
  EXPECT_EQ(json["pieces"].size(), map.pieces.size());
  EXPECT_EQ(json["bytes_total"], file.text.size());
}

TEST(CutMap, HpglSpansHoldOnlyTheirPiecesCoordinates) { check_map("hpgl-pen-plotter", true); }
TEST(CutMap, GcodeSpansHoldOnlyTheirPiecesMovesAndComment) { check_map("grbl-drag-knife", false); }

TEST(CutMap, FormatsWithoutOffsetsGiveNoPieces) {
  CutFile file;  // a DXF: its writer records no stroke offsets
  file.program = plan_cut_program(placed_pieces(shoe_layout(), shoe_instance(), SheetRef{}), profile_named("hpgl-pen-plotter"));
  file.text = "0\nSECTION\n";
  ASSERT_FALSE(file.program.strokes.empty());
  const CutMap map = make_cut_map(file);
  EXPECT_TRUE(map.pieces.empty());
  EXPECT_EQ(map.bytes_total, file.text.size());
}

}  // namespace
}  // namespace lastcut::test
