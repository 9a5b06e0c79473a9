#include "engine/toolpath/dxf_writer.hpp"

#include <cstdio>
#include <sstream>

namespace lastcut {
namespace {

class DxfOut {
 public:
  void pair(int code, const std::string& value) { out_ << code << "\n" << value << "\n"; }
  void pair(int code, int value) { pair(code, std::to_string(value)); }
  void number(int code, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6f", value);
    pair(code, buffer);
  }
  std::string handle() {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%X", next_handle_++);
    return buffer;
  }
  int next_handle() const { return next_handle_; }
  std::string text() const { return out_.str(); }

 private:
  std::ostringstream out_;
  int next_handle_ = 0x20;
};

// Layer colours (ACI): CUT white/black, MARK red, TEXT blue.
struct LayerDef {
  const char* name;
  int color;
};
constexpr LayerDef kLayers[] = {{"0", 7}, {"CUT", 7}, {"MARK", 1}, {"TEXT", 5}};

void polyline(DxfOut& out, const std::string& layer, const std::vector<Point2>& points_mm, bool closed) {
  out.pair(0, "LWPOLYLINE");
  out.pair(5, out.handle());
  out.pair(100, "AcDbEntity");
  out.pair(8, layer);
  out.pair(100, "AcDbPolyline");
  out.pair(90, static_cast<int>(points_mm.size()));
  out.pair(70, closed ? 1 : 0);
  for (const Point2& point : points_mm) {
    out.number(10, point.x());
    out.number(20, point.y());
  }
}

void line(DxfOut& out, const std::string& layer, const Point2& a, const Point2& b) {
  out.pair(0, "LINE");
  out.pair(5, out.handle());
  out.pair(100, "AcDbEntity");
  out.pair(8, layer);
  out.pair(100, "AcDbLine");
  out.number(10, a.x());
  out.number(20, a.y());
  out.number(30, 0.0);
  out.number(11, b.x());
  out.number(21, b.y());
  out.number(31, 0.0);
}

}  // namespace

std::string write_dxf(const CutProgram& program) {
  DxfOut entities;
  Point2 low = Point2::Zero(), high(program.work_area_x_mm, program.work_area_y_mm);
  for (const ProgramPiece& piece : program.pieces) {
    polyline(entities, "CUT", piece.outline_mm.points, true);
    for (const Point2& point : piece.outline_mm.points) {
      low = low.cwiseMin(point);
      high = high.cwiseMax(point);
    }
  }
  for (const Stroke& stroke : program.tip_strokes) {
    if (stroke.tool == ToolRole::Mark && stroke.points_mm.size() == 2) {
      line(entities, "MARK", stroke.points_mm[0], stroke.points_mm[1]);
    } else if (stroke.tool == ToolRole::Mark) {
      polyline(entities, "MARK", stroke.points_mm, false);
    } else if (stroke.tool == ToolRole::Pen) {
      polyline(entities, "TEXT", stroke.points_mm, false);
    }
  }

  DxfOut out;
  out.pair(0, "SECTION");
  out.pair(2, "HEADER");
  out.pair(9, "$ACADVER");
  out.pair(1, "AC1015");
  out.pair(9, "$INSUNITS");
  out.pair(70, 4);  // millimetres
  out.pair(9, "$MEASUREMENT");
  out.pair(70, 1);  // metric
  out.pair(9, "$EXTMIN");
  out.number(10, low.x());
  out.number(20, low.y());
  out.number(30, 0.0);
  out.pair(9, "$EXTMAX");
  out.number(10, high.x());
  out.number(20, high.y());
  out.number(30, 0.0);
  out.pair(9, "$HANDSEED");
  char seed[32];
  std::snprintf(seed, sizeof seed, "%X", entities.next_handle() + 0x100);
  out.pair(5, seed);
  out.pair(0, "ENDSEC");

  out.pair(0, "SECTION");
  out.pair(2, "TABLES");
  out.pair(0, "TABLE");
  out.pair(2, "LTYPE");
  out.pair(5, "5");
  out.pair(100, "AcDbSymbolTable");
  out.pair(70, 1);
  out.pair(0, "LTYPE");
  out.pair(5, "14");
  out.pair(100, "AcDbSymbolTableRecord");
  out.pair(100, "AcDbLinetypeTableRecord");
  out.pair(2, "CONTINUOUS");
  out.pair(70, 0);
  out.pair(3, "Solid line");
  out.pair(72, 65);
  out.pair(73, 0);
  out.number(40, 0.0);
  out.pair(0, "ENDTAB");
  out.pair(0, "TABLE");
  out.pair(2, "LAYER");
  out.pair(5, "2");
  out.pair(100, "AcDbSymbolTable");
  out.pair(70, static_cast<int>(std::size(kLayers)));
  int layer_handle = 0x10;
  for (const LayerDef& layer : kLayers) {
    out.pair(0, "LAYER");
    char handle[16];
    std::snprintf(handle, sizeof handle, "%X", layer_handle++);
    out.pair(5, handle);
    out.pair(100, "AcDbSymbolTableRecord");
    out.pair(100, "AcDbLayerTableRecord");
    out.pair(2, layer.name);
    out.pair(70, 0);
    out.pair(62, layer.color);
    out.pair(6, "CONTINUOUS");
  }
  out.pair(0, "ENDTAB");
  out.pair(0, "ENDSEC");

  out.pair(0, "SECTION");
  out.pair(2, "BLOCKS");
  out.pair(0, "ENDSEC");

  out.pair(0, "SECTION");
  out.pair(2, "ENTITIES");
  std::string text = out.text() + entities.text();
  DxfOut tail;
  tail.pair(0, "ENDSEC");
  tail.pair(0, "EOF");
  return text + tail.text();
}

}  // namespace lastcut
