// DXF pattern outlines (see reference_outline.hpp for the rules).
#include <string>
#include <utility>
#include <vector>

#include "engine/compare/reference_outline.hpp"
#include "engine/core/dxf_reader.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/mold/mold_dxf.hpp"

namespace lastcut {

Mold read_dxf_outline(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path)) throw EngineError("cannot read pattern file " + path.string());
  const DxfDrawing drawing = read_dxf_drawing(path);
  const double scale = dxf_millimetres_per_unit(path, drawing.insunits, "pattern");
  bool has_mark_lines = false;
  for (const DxfLine& line : drawing.lines) has_mark_lines = has_mark_lines || line.layer == "MARK";

  std::vector<Polygon2> rings;
  int open_count = 0;
  bool cut_layer_outline = false;
  for (const DxfPolyline& polyline : drawing.polylines) {
    if (!polyline.closed || polyline.vertices.size() < 2) {
      ++open_count;
      continue;
    }
    Polygon2 ring;
    ring.points = flatten_dxf_polyline(polyline, kCurveTolerance_mm / scale);
    for (auto& p : ring.points) p *= scale;
    cut_layer_outline = cut_layer_outline || polyline.layer == "CUT";
    rings.push_back(std::move(ring));
  }
  Mold mold;
  mold.name = path.stem().string();
  // A lastcut mold (one outline on CUT, notches on MARK) keeps its marks; its reader checks the rest.
  if (cut_layer_outline && has_mark_lines && drawing.insunits == 4 && rings.size() == 1) {
    mold = read_mold_dxf(path);
    if (mold.name.empty()) mold.name = path.stem().string();
    return mold;
  }
  mold.outline = largest_closed_outline(path, std::move(rings), open_count);
  return mold;
}

}  // namespace lastcut
