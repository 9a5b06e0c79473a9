#include "engine/style/forme_dxf.hpp"

#include "engine/core/dxf_document.hpp"
#include "engine/style/forme_drawing.hpp"

namespace lastcut {
namespace {

constexpr double kLandmarkText_mm = 2.5;  // heights of the landmark names and of the note
constexpr double kNoteText_mm = 3.5;
constexpr double kNoteGap_mm = 15.0;      // the note's first line this far below the forme

constexpr const char* kNote[] = {
    "Draw each style line on a layer LINE-name (one half only: LINE-medial-name, LINE-lateral-name).",
    "End it on the feather line, the top edge, the centre line or another line.",
    "Name each piece with a TEXT on layer PIECES inside it (\"medial ...\" for a piece on the medial half).",
    "Keep this drawing's place and scale; save it as DXF beside style.toml (docs/style-authoring.md)."};

}  // namespace

std::string forme_dxf(const FormeLayout& layout) {
  const std::string example_layer = std::string(kFormeLinePrefix) + "example";
  DxfDocument dxf(DxfVersion::R12, {{"0", 7},
                                    {"LATERAL", 5},
                                    {"MEDIAL", 1},
                                    {"FEATHER", 3},
                                    {"TOP", 4},
                                    {"CENTRE", 6},
                                    {"LANDMARKS", 2},
                                    {kFormePiecesLayer, 7},
                                    {example_layer, 30}});
  Point2 low = Point2::Constant(INFINITY), high = Point2::Constant(-INFINITY);
  for (const FormeHalfLayout& half : layout.halves) {
    const std::string name = half.segment->name;
    const std::vector<Point2> outline = half.outline();
    dxf.polyline(name == "medial" ? "MEDIAL" : "LATERAL", outline, true);
    for (const Point2& p : outline) low = low.cwiseMin(p), high = high.cwiseMax(p);
    dxf.polyline("FEATHER", half.edge_points(EdgeKind::Feather), false);
    dxf.polyline("TOP", half.edge_points(EdgeKind::Top), false);
    dxf.polyline("CENTRE", half.edge_points(EdgeKind::FrontSeam), false);
    dxf.polyline("CENTRE", half.edge_points(EdgeKind::BackSeam), false);
    for (const char* landmark : {"toe", "heel", "top_front", "top_back"}) {
      const Point2 at = half.landmark(landmark);
      dxf.point("LANDMARKS", at);
      dxf.text("LANDMARKS", at + Point2(1, 1) * kLandmarkText_mm / 2, kLandmarkText_mm, name + " " + landmark);
    }
  }
  for (std::size_t k = 0; k < std::size(kNote); ++k)
    dxf.text("0", {low.x(), low.y() - kNoteGap_mm - 2.0 * kNoteText_mm * static_cast<double>(k)}, kNoteText_mm, kNote[k]);
  return dxf.str();
}

}  // namespace lastcut
