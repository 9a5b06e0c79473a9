// Pattern pieces -> nest items; see pattern_items.hpp.
#include "engine/nest/pattern_items.hpp"

#include <cmath>
#include <numbers>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

void check_piece(const PatternPiece& piece, const PatternNestSpec& spec) {
  const std::string name = "piece \"" + piece.name + "\"";
  if (piece.quantity < 1) throw EngineError(name + ": quantity " + std::to_string(piece.quantity) + " is not a positive count");
  Polygon2 outline{piece.cut_line_mm};
  if (piece.cut_line_mm.size() < 3 || !(std::abs(signed_area(outline)) > 0))
    throw EngineError(name + ": its cut line encloses no area");
  auto check_lines = [&](const std::vector<std::vector<Point2>>& lines, const char* kind) {
    for (size_t k = 0; k < lines.size(); ++k)
      if (lines[k].size() < 2)
        throw EngineError(name + ": " + kind + " " + std::to_string(k + 1) + " has " + std::to_string(lines[k].size()) +
                          " point(s), a drawn line needs at least 2");
  };
  check_lines(piece.internal_lines_mm, "internal line");
  if (spec.draw_sew_lines) check_lines(piece.sew_lines_mm, "sew line");
  if (spec.rules) {
    const PieceRules rules = spec.rules(piece);
    if (rules.grain_tolerance_deg && !(*rules.grain_tolerance_deg >= 0 && *rules.grain_tolerance_deg <= 90))
      throw EngineError(name + ": a grain tolerance must be 0..90 deg");
  }
}

// The item's grain: the grain line's direction (degrees counter-clockwise from +x), mirrored for a twin.
std::optional<double> grain_of(const PatternPiece& piece, double sign) {
  if (!piece.grain_line_mm) return std::nullopt;
  const Point2 along = (*piece.grain_line_mm)[1] - (*piece.grain_line_mm)[0];
  if (!(along.norm() > 0)) return std::nullopt;
  return std::atan2(along.y(), sign * along.x()) * 180.0 / std::numbers::pi;
}

// The lines the pen draws on the item, mirrored (x -> -x) for a twin like its outline.
std::vector<std::vector<Point2>> drawn_lines_of(const PatternPiece& piece, const PatternNestSpec& spec, double sign) {
  std::vector<std::vector<Point2>> lines;
  auto add = [&](const std::vector<std::vector<Point2>>& from) {
    for (const std::vector<Point2>& line : from) {
      lines.emplace_back();
      for (const Point2& p : line) lines.back().emplace_back(sign * p.x(), p.y());
    }
  };
  add(piece.internal_lines_mm);
  if (spec.draw_sew_lines) add(piece.sew_lines_mm);
  return lines;
}

}  // namespace

std::vector<NestItem> items_from_pattern(const std::vector<PatternPiece>& pieces, const PatternNestSpec& spec) {
  if (pieces.empty()) throw EngineError("no pattern pieces to nest");
  if (spec.sets < 1) throw EngineError("at least one set of the pattern pieces is needed");
  if (!(spec.notch_depth_mm > 0)) throw EngineError("the notch depth must be positive");
  std::vector<NestItem> items;
  int id = 0;
  for (const PatternPiece& piece : pieces) {
    check_piece(piece, spec);
    const PieceRules rules = spec.rules ? spec.rules(piece) : PieceRules{};
    for (int twin = 0; twin < (spec.mirrored_twins ? 2 : 1); ++twin) {
      const double sign = twin ? -1.0 : 1.0;
      NestItem item;
      item.id = id++;
      item.demand = piece.quantity * spec.sets;
      item.allowed_rotations_deg = spec.rotations_deg;
      item.label = spec.label ? spec.label(piece, twin != 0)
                              : piece.name + (piece.size.empty() ? "" : " " + piece.size) + (twin ? " (other foot)" : "");
      for (const Point2& p : piece.cut_line_mm) item.shape.points.emplace_back(sign * p.x(), p.y());
      make_counter_clockwise(item.shape);
      for (const PatternNotch& notch : piece.notches) {
        const Point2 at(sign * notch.at_mm.x(), notch.at_mm.y());
        const Point2 inward(sign * notch.inward.x(), notch.inward.y());
        item.marks.push_back({"notch", at, at + spec.notch_depth_mm * inward.normalized()});
      }
      item.drawn_lines_mm = drawn_lines_of(piece, spec, sign);
      item.min_quality = rules.min_quality;
      if (rules.grain_tolerance_deg) {
        item.grain_deg = grain_of(piece, sign);
        if (item.grain_deg) item.grain_tolerance_deg = *rules.grain_tolerance_deg;
      }
      // The two feet's copies of one piece (the first item of this name and index is its key).
      if (spec.mirrored_twins) item.mirror_key = std::to_string(items.size() - static_cast<std::size_t>(twin)) + " " + piece.name;
      items.push_back(std::move(item));
    }
  }
  return items;
}

}  // namespace lastcut
