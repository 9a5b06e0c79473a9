#pragma once
// Reading ASCII DXF drawings: the polylines (LWPOLYLINE, POLYLINE + VERTEX + SEQEND), LINEs, ARCs and
// TEXTs (MTEXT read as TEXT) of the ENTITIES section with their layers, the other entities' types and
// layers (so a reader can refuse what it does not take instead of losing it), the layer table's names,
// and the drawing unit ($INSUNITS). Shared by the
// pattern reader (engine/compare) and the hide reader (engine/nest/hide_file.hpp), which each apply
// their own layer rules. Coordinates stay in drawing units; dxf_millimetres_per_unit converts.
// Every refusal is an EngineError of one line that names the file.
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

struct DxfVertex {
  Point2 point = Point2::Zero();  // drawing units
  double bulge = 0.0;             // tan(arc angle / 4) of the segment to the next vertex; 0 = straight
};

struct DxfPolyline {
  std::string layer;
  std::vector<DxfVertex> vertices;
  bool closed = false;  // flag 70 bit 1, or the last vertex repeats the first (then dropped)
};

struct DxfLine {
  std::string layer;
  Point2 from = Point2::Zero(), to = Point2::Zero();  // drawing units
};

struct DxfText {
  std::string layer;
  std::string text;
  Point2 at = Point2::Zero();  // insertion point (group 10), drawing units
};

struct DxfArc {
  std::string layer;
  Point2 centre = Point2::Zero();  // drawing units
  double radius = 0.0;
  double start_deg = 0.0, end_deg = 0.0;  // counter-clockwise from start to end
};

// An entity the reader does not take apart (SPLINE, CIRCLE, ELLIPSE, INSERT, ...).
struct DxfOtherEntity {
  std::string type;
  std::string layer;
};

struct DxfDrawing {
  int insunits = 0;  // $INSUNITS; 0 when absent
  std::vector<DxfPolyline> polylines;
  std::vector<DxfLine> lines;
  std::vector<DxfText> texts;
  std::vector<DxfArc> arcs;
  std::vector<DxfOtherEntity> others;
  std::vector<std::string> layers;  // the LAYER table's names, in table order
};

// Reads the file. Throws EngineError when it cannot be read or is not a DXF file.
DxfDrawing read_dxf_drawing(const std::filesystem::path& path);

// mm per drawing unit: $INSUNITS 4 mm, 5 cm, 6 m, 1 inch, 0 (unitless) read as mm. Any other unit
// is refused: "<path>: drawing units $INSUNITS 2 are not supported; save the <what> in mm, cm, m or inches".
double dxf_millimetres_per_unit(const std::filesystem::path& path, int insunits, const std::string& what);

// The closed polyline as points (drawing units), bulge arcs flattened within `tolerance` (drawing units).
std::vector<Point2> flatten_dxf_polyline(const DxfPolyline& polyline, double tolerance);

}  // namespace lastcut
