#pragma once
// The shipped derby (config/styles/derby: lines.obj and the [[piece]] labels, drawn in 3D on the generated
// EU 42 right last) drawn on that last's forme, as a pattern maker would draw it in CAD: for the forme
// style tests (tests/style/forme_style_test.cpp, tests/cli_flatten/cli_style_forme_test.cpp).
//
// Each 3D line is taken onto the forme through the reference's own halves: the style transfer from the
// reference to itself gives every point's half and its place in that half's flattening (with the line's
// crossings of the feather line and the centre seams found exactly), and forme_layout places it on the
// forme. Each stretch on one half becomes a polyline on layer LINE-medial-<name> or LINE-lateral-<name>;
// each label a text on layer PIECES. The lift (engine/style/forme_lift.hpp) is judged against the 3D
// lines themselves, not against this drawing.
#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "engine/core/dxf_document.hpp"
#include "engine/style/forme_drawing.hpp"
#include "engine/style/forme_layout.hpp"
#include "engine/style/style_lines_obj.hpp"
#include "engine/style/style_transfer.hpp"

namespace lastcut::test {

struct DrawnPolyline {
  std::string layer;
  std::vector<Point2> points_mm;  // on the forme
};

struct DrawnText {
  std::string text;
  Point2 at_mm = Point2::Zero();
};

inline int forme_half_index(const std::string& half) { return half == "medial" ? 0 : 1; }

// A 3D line (reference scan frame) on the forme: its stretches on each half.
inline std::vector<DrawnPolyline> line_on_forme(const StyleTransfer& identity, const FormeLayout& layout, const StyleLine& line) {
  constexpr double kBreak_mm = 3.0;  // a jump this long in 3D: the line left the upper between two points
  const TransferredCurve curve = identity.transfer_curve(line.points_mm);
  std::vector<std::vector<const TransferredPoint*>> stretches;
  for (std::size_t i = 0; i < curve.points.size(); ++i) {
    const TransferredPoint& p = curve.points[i];
    const bool same = !stretches.empty() && stretches.back().back()->half == p.half &&
                      (stretches.back().back()->position_mm - p.position_mm).norm() < kBreak_mm;
    if (!same) stretches.emplace_back();
    stretches.back().push_back(&p);
  }
  // A closed line that starts inside a half: its last stretch runs on into its first.
  const bool closed = (line.points_mm.front() - line.points_mm.back()).norm() < 1e-9;
  if (closed && stretches.size() > 1 && stretches.front().front()->half == stretches.back().back()->half &&
      (stretches.front().front()->position_mm - stretches.back().back()->position_mm).norm() < 1e-9) {
    stretches.back().insert(stretches.back().end(), stretches.front().begin() + 1, stretches.front().end());
    stretches.erase(stretches.begin());
  }
  std::vector<DrawnPolyline> drawn;
  for (const auto& stretch : stretches) {
    if (stretch.size() < 2) continue;
    DrawnPolyline polyline{std::string(kFormeLinePrefix) + stretch.front()->half + "-" + line.name, {}};
    const FormeHalfLayout& half = layout.halves[static_cast<std::size_t>(forme_half_index(stretch.front()->half))];
    for (const TransferredPoint* p : stretch) polyline.points_mm.push_back(half.to_forme(p->forme_uv_mm));
    drawn.push_back(polyline);
  }
  return drawn;
}

// Where a 3D point (reference scan frame) lies on the forme, on its own half.
inline Point2 point_on_forme(const StyleTransfer& identity, const FormeLayout& layout, const Eigen::Vector3d& point_mm) {
  const TransferredPoint p = identity.transfer_point(point_mm).value();
  return layout.halves[static_cast<std::size_t>(forme_half_index(p.half))].to_forme(p.forme_uv_mm);
}

// The entities of a drawing as an R12 DXF file.
inline std::string drawing_dxf(const std::vector<DrawnPolyline>& lines, const std::vector<DrawnText>& texts) {
  std::vector<DxfLayer> layers{{kFormePiecesLayer, 7}};
  for (const DrawnPolyline& line : lines) layers.push_back({line.layer, 1});
  DxfDocument dxf(DxfVersion::R12, layers);
  for (const DrawnPolyline& line : lines) dxf.polyline(line.layer, line.points_mm, false);
  for (const DrawnText& text : texts) dxf.text(kFormePiecesLayer, text.at_mm, 5.0, text.text);
  return dxf.str();
}

// The forme file as `lastcut style new` wrote it with the entities of another DXF file added, as a CAD
// program saves a drawing made on it.
inline std::string with_entities_of(const std::string& forme, const std::string& drawing) {
  const std::string entities = "ENTITIES\n", end = "0\nENDSEC\n0\nEOF\n";
  const std::size_t from = drawing.find(entities) + entities.size();
  const std::string added = drawing.substr(from, drawing.rfind(end) - from);
  std::string out = forme;
  return out.insert(out.rfind(end), added);
}

}  // namespace lastcut::test
