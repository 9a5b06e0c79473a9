#pragma once
// DxfDocument: one ASCII DXF file in millimetres, built entity by entity and written whole.
// Two flavours of the same drawing:
//   R12   (AC1009) no handles, outlines as POLYLINE + VERTEX + SEQEND: the most widely read
//         version, for pattern CAD and older cutter software (mold files).
//   R2000 (AC1015) every object carries a handle and its subclass markers, outlines as
//         LWPOLYLINE (cut files for current CAD).
// Structure of both: HEADER ($ACADVER, $INSUNITS 4 = mm, $MEASUREMENT 1 = metric, $EXTMIN/$EXTMAX,
// R2000 also $HANDSEED), TABLES (LTYPE CONTINUOUS, the caller's LAYERs), BLOCKS (empty unless the
// caller defines blocks, R12 only), ENTITIES, EOF. Numbers are written with 6 decimals (1 nm); z is
// always 0.
// Blocks (DXF-AAMA pattern pieces): entities drawn between begin_block and end_block go into that
// block's definition instead of ENTITIES; insert() places a defined block in ENTITIES. Only R12:
// R2000 would need a BLOCK_RECORD table entry and handles for each block.
#include <map>
#include <optional>
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
  // Single-line TEXT, left baseline at `at_mm`, capital height `height_mm`.
  void text(const std::string& layer, const Point2& at_mm, double height_mm, const std::string& text);
  // A POINT (a mark with no extent, shown as the viewer's point style); `angle_deg` (group 50,
  // counter-clockwise from +x) is what DXF-AAMA notches carry.
  void point(const std::string& layer, const Point2& at_mm, std::optional<double> angle_deg = std::nullopt);
  // Widens $EXTMIN/$EXTMAX beyond the entities (e.g. to the machine's work area).
  void include_in_extents(const Point2& point_mm);

  // Starts the definition of block `name` (base point 0,0) on `layer`; R12 only (std::logic_error
  // otherwise, or when a block is already open or the name is taken). Names are written as given:
  // the caller keeps them to letters, digits, '_', '-' and '$' (what R12 allows).
  void begin_block(const std::string& name, const std::string& layer);
  void end_block();
  // Places the defined block `name` with its base point at `at_mm` (scale 1, no rotation); the
  // extents grow by the block's own extents moved there.
  void insert(const std::string& layer, const std::string& name, const Point2& at_mm);

  // The complete file.
  std::string str() const;

 private:
  class Writer;
  void entity_start(Writer& out, const char* type, const std::string& layer, const char* subclass);
  void extend(const Point2& point_mm);
  std::string& body();  // the open block's definition, else ENTITIES

  struct Extents {
    bool any = false;
    Point2 low_mm = Point2::Zero(), high_mm = Point2::Zero();
    void add(const Point2& point_mm);
  };

  DxfVersion version_;
  std::vector<DxfLayer> layers_;
  std::string entities_;
  std::string blocks_;              // BLOCK ... ENDBLK definitions, in order
  std::string open_block_;          // name of the block being defined; empty outside
  std::string open_block_layer_;
  std::map<std::string, Extents> block_extents_;  // defined blocks, by name
  Extents extents_;
  int next_entity_handle_ = 0x100;  // table objects take the handles below
};

}  // namespace lastcut
