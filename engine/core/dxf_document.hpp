#pragma once
// DxfDocument: one ASCII DXF file in millimetres, built entity by entity and written whole.
// Two flavours of the same drawing:
//   R12   (AC1009) no handles, outlines as POLYLINE + VERTEX + SEQEND: the most widely read
//         version, for pattern CAD and older cutter software (mold files).
//   R2000 (AC1015) every object carries a handle and its subclass markers, outlines as
//         LWPOLYLINE (cut files for current CAD).
// Structure of both: HEADER ($ACADVER, $INSUNITS 4 = mm, $MEASUREMENT 1 = metric, $EXTMIN/$EXTMAX,
// R2000 also $HANDSEED), TABLES (LTYPE CONTINUOUS, the caller's LAYERs), an empty BLOCKS section,
// ENTITIES, EOF. Numbers are written with 6 decimals (1 nm); z is always 0.
#include <string>
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

enum class DxfVersion { R12, R2000 };

struct DxfLayer {
  std::string name;
  int color_aci = 7;  // AutoCAD colour index: 1 red, 3 green, 5 blue, 7 white/black
};

class DxfDocument {
 public:
  // `layers` in table order; entities may only use these names (not checked: DXF readers
  // create a missing layer with default colour).
  DxfDocument(DxfVersion version, std::vector<DxfLayer> layers);

  // points_mm #P (closing edge implicit when `closed`).
  void polyline(const std::string& layer, const std::vector<Point2>& points_mm, bool closed);
  void line(const std::string& layer, const Point2& from_mm, const Point2& to_mm);
  // A POINT (a mark with no extent, shown as the viewer's point style).
  void point(const std::string& layer, const Point2& at_mm);
  // Single-line TEXT, left baseline at `at_mm`, capital height `height_mm`.
  void text(const std::string& layer, const Point2& at_mm, double height_mm, const std::string& text);
  // Widens $EXTMIN/$EXTMAX beyond the entities (e.g. to the machine's work area).
  void include_in_extents(const Point2& point_mm);

  // The complete file.
  std::string str() const;

 private:
  class Writer;
  void entity_start(Writer& out, const char* type, const std::string& layer, const char* subclass);
  void extend(const Point2& point_mm);

  DxfVersion version_;
  std::vector<DxfLayer> layers_;
  std::string entities_;
  bool has_extents_ = false;
  Point2 low_mm_ = Point2::Zero(), high_mm_ = Point2::Zero();
  int next_entity_handle_ = 0x100;  // table objects take the handles below
};

}  // namespace lastcut
