#pragma once
// What the DXF-AAMA tests read and write: sample pieces with every kind of line, and DXF text
// written by hand, group by group, as other pattern CAD writes it (independent of DxfDocument, so
// the reader is tested on files our writer did not make).
#include <cmath>
#include <string>
#include <vector>

#include "engine/pattern/pattern_piece.hpp"

namespace lastcut::test {

// A counter-clockwise outline like a vamp: a superellipse of half axes a, b around `centre`.
inline std::vector<Point2> vamp_outline(const Point2& centre, double a_mm, double b_mm, int points) {
  std::vector<Point2> outline;
  for (int i = 0; i < points; ++i) {
    const double t = 2.0 * M_PI * i / points;
    const double c = std::cos(t), s = std::sin(t);
    // Exponent 0.8: fuller than an ellipse; odd coordinates exercise the 6 decimals of the file.
    outline.emplace_back(centre.x() + a_mm * std::copysign(std::pow(std::abs(c), 0.8), c),
                         centre.y() + b_mm * std::copysign(std::pow(std::abs(s), 0.8), s));
  }
  return outline;
}

// A piece with a net line (closed), a sew line (open), notches at three outline points pointing
// at the centre, and a grain line along x.
inline PatternPiece sample_piece(const std::string& name, const std::string& size, const Point2& centre,
                                 double a_mm, double b_mm) {
  PatternPiece piece;
  piece.name = name;
  piece.style = "derby 2024";
  piece.size = size;
  piece.category = "upper leather";
  piece.annotation = "right";
  piece.quantity = 2;
  piece.cut_line_mm = vamp_outline(centre, a_mm, b_mm, 48);
  std::vector<Point2> net = vamp_outline(centre, a_mm - 8.0, b_mm - 8.0, 48);
  net.push_back(net.front());
  piece.internal_lines_mm.push_back(net);
  piece.sew_lines_mm.push_back({centre + Point2(-a_mm / 2, b_mm / 3), centre + Point2(0.0, b_mm / 2.5),
                                centre + Point2(a_mm / 2, b_mm / 3)});
  for (int k : {0, 12, 30}) {
    const Point2 at = piece.cut_line_mm[k];
    piece.notches.push_back({at, Point2((centre - at).normalized())});
  }
  piece.grain_line_mm = std::array<Point2, 2>{centre + Point2(-a_mm / 2, 0.0), centre + Point2(a_mm / 2, 0.0)};
  return piece;
}

// DXF text group by group.
class HandDxf {
 public:
  HandDxf& pair(int code, const std::string& value) {
    text_ += std::to_string(code) + "\n" + value + "\n";
    return *this;
  }
  HandDxf& pair(int code, double value) { return pair(code, std::to_string(value)); }
  HandDxf& header(int insunits) {
    pair(0, "SECTION").pair(2, "HEADER").pair(9, "$ACADVER").pair(1, "AC1009");
    pair(9, "$INSUNITS").pair(70, std::to_string(insunits));
    return pair(0, "ENDSEC");
  }
  HandDxf& section(const std::string& name) { return pair(0, "SECTION").pair(2, name); }
  HandDxf& end_section() { return pair(0, "ENDSEC"); }
  HandDxf& block(const std::string& name) {
    return pair(0, "BLOCK").pair(8, "1").pair(2, name).pair(70, "0").pair(10, 0.0).pair(20, 0.0).pair(3, name);
  }
  HandDxf& end_block() { return pair(0, "ENDBLK").pair(8, "1"); }
  HandDxf& insert(const std::string& name, const Point2& at) {
    return pair(0, "INSERT").pair(8, "1").pair(2, name).pair(10, at.x()).pair(20, at.y());
  }
  // R12 POLYLINE + VERTEX + SEQEND.
  HandDxf& polyline(const std::string& layer, const std::vector<Point2>& points, bool closed) {
    pair(0, "POLYLINE").pair(8, layer).pair(66, "1").pair(70, closed ? "1" : "0");
    for (const Point2& p : points) pair(0, "VERTEX").pair(8, layer).pair(10, p.x()).pair(20, p.y());
    return pair(0, "SEQEND").pair(8, layer);
  }
  // R14+ LWPOLYLINE; `bulges` per vertex (empty: straight).
  HandDxf& lwpolyline(const std::string& layer, const std::vector<Point2>& points, bool closed,
                      const std::vector<double>& bulges = {}) {
    pair(0, "LWPOLYLINE").pair(8, layer).pair(90, std::to_string(points.size())).pair(70, closed ? "1" : "0");
    for (size_t i = 0; i < points.size(); ++i) {
      pair(10, points[i].x()).pair(20, points[i].y());
      if (i < bulges.size() && bulges[i] != 0.0) pair(42, bulges[i]);
    }
    return *this;
  }
  HandDxf& line(const std::string& layer, const Point2& from, const Point2& to) {
    return pair(0, "LINE").pair(8, layer).pair(10, from.x()).pair(20, from.y()).pair(11, to.x()).pair(21, to.y());
  }
  HandDxf& text(const std::string& layer, const std::string& value) {
    return pair(0, "TEXT").pair(8, layer).pair(10, 0.0).pair(20, 0.0).pair(40, 2.5).pair(1, value);
  }
  HandDxf& eof() { return pair(0, "EOF"); }
  const std::string& str() const { return text_; }

 private:
  std::string text_;
};

// A square of side `side` at the origin, counter-clockwise.
inline std::vector<Point2> square(double side) { return {{0, 0}, {side, 0}, {side, side}, {0, side}}; }

// A whole file of one piece block "vamp" (placed once) holding `piece_entities` after its name text.
template <typename Fill>
std::string one_piece_file(int insunits, Fill&& piece_entities) {
  HandDxf dxf;
  dxf.header(insunits).section("BLOCKS").block("vamp").text("1", "Piece Name: vamp");
  piece_entities(dxf);
  dxf.end_block().end_section().section("ENTITIES").insert("vamp", Point2(0, 0)).end_section().eof();
  return dxf.str();
}

}  // namespace lastcut::test
