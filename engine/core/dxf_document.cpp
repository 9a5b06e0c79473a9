#include "engine/core/dxf_document.hpp"

#include <cstdio>
#include <stdexcept>
#include <utility>

namespace lastcut {

// Group-code/value pairs, one per two lines, appended to a string.
class DxfDocument::Writer {
 public:
  explicit Writer(std::string& out) : out_(out) {}
  void pair(int code, const std::string& value) {
    out_ += std::to_string(code);
    out_ += '\n';
    out_ += value;
    out_ += '\n';
  }
  void pair(int code, int value) { pair(code, std::to_string(value)); }
  void number(int code, double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.6f", value);
    pair(code, text);
  }
  void hex(int code, int value) {
    char text[32];
    std::snprintf(text, sizeof text, "%X", value);
    pair(code, text);
  }
  // x, y, z at codes first, first + 10, first + 20.
  void point(int first_code, const Point2& p) {
    number(first_code, p.x());
    number(first_code + 10, p.y());
    number(first_code + 20, 0.0);
  }

 private:
  std::string& out_;
};

DxfDocument::DxfDocument(DxfVersion version, std::vector<DxfLayer> layers)
    : version_(version), layers_(std::move(layers)) {}

void DxfDocument::Extents::add(const Point2& point_mm) {
  low_mm = any ? Point2(low_mm.cwiseMin(point_mm)) : point_mm;
  high_mm = any ? Point2(high_mm.cwiseMax(point_mm)) : point_mm;
  any = true;
}

// Inside a block the points are the block's own; they reach the drawing's extents through insert().
void DxfDocument::extend(const Point2& point_mm) {
  (open_block_.empty() ? extents_ : block_extents_[open_block_]).add(point_mm);
}

std::string& DxfDocument::body() { return open_block_.empty() ? entities_ : blocks_; }

void DxfDocument::include_in_extents(const Point2& point_mm) { extents_.add(point_mm); }

void DxfDocument::begin_block(const std::string& name, const std::string& layer) {
  if (version_ != DxfVersion::R12) throw std::logic_error("DxfDocument: blocks are written in R12 files only");
  if (!open_block_.empty() || name.empty() || block_extents_.count(name))
    throw std::logic_error("DxfDocument: block '" + name + "' is open, empty or defined twice");
  open_block_ = name;
  open_block_layer_ = layer;
  block_extents_[name];
  Writer out(blocks_);
  out.pair(0, "BLOCK");
  out.pair(8, layer);
  out.pair(2, name);
  out.pair(70, 0);
  out.point(10, Point2::Zero());
  out.pair(3, name);
}

void DxfDocument::end_block() {
  if (open_block_.empty()) throw std::logic_error("DxfDocument: end_block without begin_block");
  Writer out(blocks_);
  out.pair(0, "ENDBLK");
  out.pair(8, open_block_layer_);
  open_block_.clear();
}

void DxfDocument::insert(const std::string& layer, const std::string& name, const Point2& at_mm) {
  const auto block = block_extents_.find(name);
  if (block == block_extents_.end() || name == open_block_)
    throw std::logic_error("DxfDocument: insert of block '" + name + "', which is not defined");
  if (block->second.any) {
    extents_.add(block->second.low_mm + at_mm);
    extents_.add(block->second.high_mm + at_mm);
  }
  Writer out(entities_);
  entity_start(out, "INSERT", layer, "AcDbBlockReference");
  out.pair(2, name);
  out.point(10, at_mm);
}

void DxfDocument::point(const std::string& layer, const Point2& at_mm, std::optional<double> angle_deg) {
  extend(at_mm);
  Writer out(body());
  entity_start(out, "POINT", layer, "AcDbPoint");
  out.point(10, at_mm);
  if (angle_deg) out.number(50, *angle_deg);
}

void DxfDocument::entity_start(Writer& out, const char* type, const std::string& layer, const char* subclass) {
  out.pair(0, type);
  if (version_ == DxfVersion::R2000) {
    out.hex(5, next_entity_handle_++);
    out.pair(100, "AcDbEntity");
  }
  out.pair(8, layer);
  if (version_ == DxfVersion::R2000) out.pair(100, subclass);
}

void DxfDocument::polyline(const std::string& layer, const std::vector<Point2>& points_mm, bool closed) {
  for (const Point2& p : points_mm) extend(p);
  Writer out(body());
  if (version_ == DxfVersion::R2000) {
    entity_start(out, "LWPOLYLINE", layer, "AcDbPolyline");
    out.pair(90, static_cast<int>(points_mm.size()));
    out.pair(70, closed ? 1 : 0);
    for (const Point2& p : points_mm) {
      out.number(10, p.x());
      out.number(20, p.y());
    }
    return;
  }
  entity_start(out, "POLYLINE", layer, nullptr);
  out.pair(66, 1);  // vertices follow
  out.point(10, Point2::Zero());
  out.pair(70, closed ? 1 : 0);
  for (const Point2& p : points_mm) {
    entity_start(out, "VERTEX", layer, nullptr);
    out.point(10, p);
  }
  entity_start(out, "SEQEND", layer, nullptr);
}

void DxfDocument::line(const std::string& layer, const Point2& from_mm, const Point2& to_mm) {
  extend(from_mm);
  extend(to_mm);
  Writer out(body());
  entity_start(out, "LINE", layer, "AcDbLine");
  out.point(10, from_mm);
  out.point(11, to_mm);
}

void DxfDocument::text(const std::string& layer, const Point2& at_mm, double height_mm, const std::string& text) {
  extend(at_mm);
  Writer out(body());
  entity_start(out, "TEXT", layer, "AcDbText");
  out.point(10, at_mm);
  out.number(40, height_mm);
  out.pair(1, text);
  if (version_ == DxfVersion::R2000) out.pair(100, "AcDbText");  // the second marker closes the text data
}

std::string DxfDocument::str() const {
  if (!open_block_.empty()) throw std::logic_error("DxfDocument: block '" + open_block_ + "' is not ended");
  const bool r2000 = version_ == DxfVersion::R2000;
  std::string file;
  Writer out(file);
  int table_handle = 1;
  auto table_object = [&](const char* record_subclass) {
    if (!r2000) return;
    out.hex(5, table_handle++);
    out.pair(100, "AcDbSymbolTableRecord");
    out.pair(100, record_subclass);
  };
  auto table_start = [&](const char* name, int entries) {
    out.pair(0, "TABLE");
    out.pair(2, name);
    if (r2000) {
      out.hex(5, table_handle++);
      out.pair(100, "AcDbSymbolTable");
    }
    out.pair(70, entries);
  };

  out.pair(0, "SECTION");
  out.pair(2, "HEADER");
  out.pair(9, "$ACADVER");
  out.pair(1, r2000 ? "AC1015" : "AC1009");
  out.pair(9, "$INSUNITS");
  out.pair(70, 4);  // millimetres
  out.pair(9, "$MEASUREMENT");
  out.pair(70, 1);  // metric
  out.pair(9, "$EXTMIN");
  out.point(10, extents_.low_mm);
  out.pair(9, "$EXTMAX");
  out.point(10, extents_.high_mm);
  if (r2000) {
    out.pair(9, "$HANDSEED");
    out.hex(5, next_entity_handle_);
  }
  out.pair(0, "ENDSEC");

  out.pair(0, "SECTION");
  out.pair(2, "TABLES");
  table_start("LTYPE", 1);
  out.pair(0, "LTYPE");
  table_object("AcDbLinetypeTableRecord");
  out.pair(2, "CONTINUOUS");
  out.pair(70, 0);
  out.pair(3, "Solid line");
  out.pair(72, 65);
  out.pair(73, 0);
  out.number(40, 0.0);
  out.pair(0, "ENDTAB");
  table_start("LAYER", static_cast<int>(layers_.size()));
  for (const DxfLayer& layer : layers_) {
    out.pair(0, "LAYER");
    table_object("AcDbLayerTableRecord");
    out.pair(2, layer.name);
    out.pair(70, 0);
    out.pair(62, layer.color_aci);
    out.pair(6, "CONTINUOUS");
  }
  out.pair(0, "ENDTAB");
  out.pair(0, "ENDSEC");

  out.pair(0, "SECTION");
  out.pair(2, "BLOCKS");
  file += blocks_;
  out.pair(0, "ENDSEC");

  out.pair(0, "SECTION");
  out.pair(2, "ENTITIES");
  file += entities_;
  out.pair(0, "ENDSEC");
  out.pair(0, "EOF");
  return file;
}

}  // namespace lastcut
