#pragma once
// Reading ASCII DXF drawings: the polylines (LWPOLYLINE, POLYLINE + VERTEX + SEQEND), LINEs, ARCs,
// POINTs, TEXTs (MTEXT read as TEXT) and INSERTs of the ENTITIES section with their layers, the same
// entities inside each BLOCK of the BLOCKS section, the other entities' types and layers (so a reader
// can refuse what it does not take instead of losing it), the layer table's names, and the drawing
// unit ($INSUNITS). Shared by the pattern reader (engine/compare), the hide reader
// (engine/nest/hide_file.hpp), the DXF-AAMA reader (engine/pattern/aama_dxf.hpp) and the forme reader
// (engine/style/forme_drawing.hpp), which each apply their own layer rules. Coordinates stay in
// drawing units; dxf_millimetres_per_unit converts.
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
  Point2 at = Point2::Zero();  // first alignment point (10/20), drawing units
};

struct DxfArc {
  std::string layer;
  Point2 centre = Point2::Zero();  // drawing units
  double radius = 0.0;
  double start_deg = 0.0, end_deg = 0.0;  // counter-clockwise from start to end
};

// An entity the reader does not take apart (SPLINE, CIRCLE, ELLIPSE, ...).
struct DxfOtherEntity {
  std::string type;
  std::string layer;
};

struct DxfPoint {
  std::string layer;
  Point2 at = Point2::Zero();  // drawing units
  bool has_angle = false;      // group 50 present (DXF-AAMA notches carry their direction there)
  double angle_deg = 0.0;      // counter-clockwise from +x
};

struct DxfInsert {
  std::string layer;
  std::string block;           // group 2
  Point2 at = Point2::Zero();  // insertion point, drawing units
};

// The entities of the ENTITIES section or of one block, each kind in file order.
struct DxfEntities {
  std::vector<DxfPolyline> polylines;
  std::vector<DxfLine> lines;
  std::vector<DxfText> texts;
  std::vector<DxfPoint> points;
  std::vector<DxfInsert> inserts;
  std::vector<DxfArc> arcs;
  std::vector<DxfOtherEntity> others;
};

struct DxfBlock {
  std::string name;
  Point2 base = Point2::Zero();  // base point (10/20), drawing units
  DxfEntities entities;
};

// The ENTITIES section is the drawing's own DxfEntities.
struct DxfDrawing : DxfEntities {
  int insunits = 0;  // $INSUNITS; 0 when absent
  int sections = 0;  // SECTIONs seen: 0 for a file of group pairs that is no drawing
  std::vector<DxfBlock> blocks;
  std::vector<std::string> layers;  // the LAYER table's names, in table order
};

// Reads the file. Throws EngineError when it cannot be read or is not a DXF file.
DxfDrawing read_dxf_drawing(const std::filesystem::path& path);
// The same for a file's content already in memory; `file_name` names it in refusals.
DxfDrawing read_dxf_drawing_text(const std::string& text, const std::string& file_name);

// mm per drawing unit: $INSUNITS 4 mm, 5 cm, 6 m, 1 inch, 0 (unitless) read as mm. Any other unit
// is refused: "<path>: drawing units $INSUNITS 2 are not supported; save the <what> in mm, cm, m or inches".
double dxf_millimetres_per_unit(const std::filesystem::path& path, int insunits, const std::string& what);

// The polyline as points (drawing units), bulge arcs flattened within `tolerance` (drawing units).
// A closed polyline gets the arc of its closing segment too (its first point is not repeated); an
// open one ends at its last vertex.
std::vector<Point2> flatten_dxf_polyline(const DxfPolyline& polyline, double tolerance);

}  // namespace lastcut
