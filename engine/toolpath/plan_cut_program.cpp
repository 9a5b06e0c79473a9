#include "engine/toolpath/plan_cut_program.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "engine/core/engine_error.hpp"
#include "engine/toolpath/drag_knife.hpp"
#include "engine/toolpath/mark_stroke.hpp"
#include "engine/toolpath/piece_contour.hpp"
#include "engine/toolpath/piece_label.hpp"
#include "engine/toolpath/planar_geometry.hpp"
#include "engine/toolpath/stroke_font.hpp"
#include "engine/toolpath/tangential_knife.hpp"
#include "engine/toolpath/travel_order.hpp"

namespace lastcut {
namespace {

// Corners below this turn do not hide the knife's entry mark.
constexpr double kStartCornerMin_deg = 30.0;
// Work-area check tolerance: coordinates are rounded to plotter units when written.
constexpr double kWorkAreaTolerance_mm = 1e-6;

std::string describe(const PlacedPiece& piece, size_t index) {
  std::string text = "piece " + std::to_string(index + 1) + " (item " + std::to_string(piece.item_id);
  if (!piece.label.empty()) text += " '" + piece.label + "'";
  return text + ")";
}

void check_point(const Point2& point, const PlacedPiece& piece, size_t index, const MachineProfile& profile) {
  if (!std::isfinite(point.x()) || !std::isfinite(point.y())) {
    throw EngineError(describe(piece, index) + " has a coordinate that is not a number");
  }
  if (point.x() < -kWorkAreaTolerance_mm || point.y() < -kWorkAreaTolerance_mm ||
      point.x() > profile.work_area_x_mm + kWorkAreaTolerance_mm ||
      point.y() > profile.work_area_y_mm + kWorkAreaTolerance_mm) {
    std::ostringstream message;
    message << describe(piece, index) << " reaches (" << point.x() << ", " << point.y()
            << ") mm, outside the work area of machine '" << profile.name << "' (" << profile.work_area_x_mm << " x "
            << profile.work_area_y_mm << " mm from the origin)";
    throw EngineError(message.str());
  }
}

PlacedPiece checked_piece(const PlacedPiece& piece, size_t index, const MachineProfile& profile) {
  for (const Point2& point : piece.outline.points) check_point(point, piece, index, profile);
  for (const PlacedMark& mark : piece.marks) {
    check_point(mark.from_mm, piece, index, profile);
    check_point(mark.to_mm, piece, index, profile);
    // A V's ends lie beside the mark, half its width off the outline point.
    for (const Point2& point : mark_stroke(mark, profile.notch)) check_point(point, piece, index, profile);
  }
  // Without a pen the drawn lines are left out, so they cannot be outside anything.
  if (profile.pen)
    for (const std::vector<Point2>& line : piece.drawn_lines_mm)
      for (const Point2& point : line) check_point(point, piece, index, profile);
  PlacedPiece clean = piece;
  clean.outline.points = without_repeated_points(piece.outline.points, 1e-6, true);
  if (clean.outline.points.size() < 3 || std::abs(signed_area(clean.outline)) < 1e-6) {
    throw EngineError(describe(piece, index) + " has no area (fewer than 3 distinct points)");
  }
  make_counter_clockwise(clean.outline);
  return clean;
}

// Where the tour visits a piece: its start corner, or for smooth pieces its lowest-left vertex.
Point2 tour_stop(const Polygon2& outline) {
  if (has_start_corner(outline, kStartCornerMin_deg)) {
    return outline.points[contour_start_vertex(outline, Point2::Zero(), kStartCornerMin_deg)];
  }
  const Point2 low = std::accumulate(outline.points.begin(), outline.points.end(), outline.points.front(),
                                     [](const Point2& a, const Point2& b) { return Point2(a.cwiseMin(b)); });
  return outline.points[contour_start_vertex(outline, low, 179.0)];
}

// The lines one after the other, each time the one with an end nearest the tool, from that end:
// short travel without a tour, for the few lines of one piece.
void add_nearest_first(std::vector<std::vector<Point2>> lines, ToolRole tool, int order_index, Point2& tool_mm,
                       CutProgram& program) {
  std::vector<bool> done(lines.size(), false);
  for (size_t step = 0; step < lines.size(); ++step) {
    size_t best = 0;
    double best_mm = INFINITY;
    bool reversed = false;
    for (size_t m = 0; m < lines.size(); ++m) {
      if (done[m]) continue;
      const double from_mm = (lines[m].front() - tool_mm).norm();
      const double to_mm = (lines[m].back() - tool_mm).norm();
      if (std::min(from_mm, to_mm) < best_mm) {
        best_mm = std::min(from_mm, to_mm);
        best = m;
        reversed = to_mm < from_mm;
      }
    }
    done[best] = true;
    std::vector<Point2> line = std::move(lines[best]);
    if (reversed) std::reverse(line.begin(), line.end());
    tool_mm = line.back();
    program.strokes.push_back(Stroke{tool, std::move(line), {}, order_index, false});
  }
}

void add_piece_strokes(const PlacedPiece& piece, int order_index, const MachineProfile& profile, Point2& tool_mm,
                       CutProgram& program) {
  ProgramPiece info{piece.item_id, piece.label, "", {}};
  if (profile.label.enabled && profile.pen) {
    const std::string text = piece_marking(order_index + 1, piece.label);
    if (const auto placed = place_text(text, piece.outline, profile.label.height_mm, profile.label.min_height_mm)) {
      info.marking = text;
      for (auto& points : text_strokes(text, placed->center_mm, placed->height_mm)) {
        program.strokes.push_back(Stroke{ToolRole::Pen, std::move(points), {}, order_index, false});
        tool_mm = program.strokes.back().points_mm.back();
      }
    }
  }
  // Drawn lines right after the label: the same tool, no change between them.
  if (profile.pen) {
    std::vector<std::vector<Point2>> drawn;
    for (const std::vector<Point2>& line : piece.drawn_lines_mm)
      if (polyline_length(line) >= 1e-6) drawn.push_back(line);
    add_nearest_first(std::move(drawn), ToolRole::Pen, order_index, tool_mm, program);
  }
  std::vector<std::vector<Point2>> marks;
  for (const PlacedMark& mark : piece.marks)
    if (std::vector<Point2> stroke = mark_stroke(mark, profile.notch); !stroke.empty()) marks.push_back(std::move(stroke));
  add_nearest_first(std::move(marks), ToolRole::Mark, order_index, tool_mm, program);
  const int start = contour_start_vertex(piece.outline, tool_mm, kStartCornerMin_deg);
  const size_t n = piece.outline.points.size();
  for (size_t k = 0; k < n; ++k) info.outline_mm.points.push_back(piece.outline.points[(start + k) % n]);
  program.strokes.push_back(
      Stroke{ToolRole::Cut, contour_cut_path(piece.outline, start, profile.overcut_mm), {}, order_index, true});
  tool_mm = program.strokes.back().points_mm.back();
  program.pieces.push_back(info);
}

// Turns tip paths into what the tool's axis must do.
std::vector<Stroke> adapt_to_tools(const std::vector<Stroke>& strokes, const MachineProfile& profile) {
  std::vector<Stroke> adapted;
  double knife_angle_deg = 0.0;
  for (const Stroke& stroke : strokes) {
    const ToolSettings& tool = profile.tool(stroke.tool);
    if (tool.kind == ToolKind::DragKnife) {
      std::optional<Point2> incoming;
      if (stroke.closed_outline && stroke.points_mm.size() >= 3) {
        // The contour returns to its start; the blade arrives along the outline's last edge.
        const Point2& start = stroke.points_mm.front();
        for (size_t k = stroke.points_mm.size() - 1; k > 0; --k) {
          if ((stroke.points_mm[k] - start).norm() < 1e-9 && (stroke.points_mm[k - 1] - start).norm() > 1e-9) {
            incoming = start - stroke.points_mm[k - 1];
            break;
          }
        }
      }
      Stroke compensated = stroke;
      compensated.points_mm = compensate_drag_knife(
          stroke.points_mm, incoming,
          DragKnifeOptions{tool.blade_offset_mm, profile.corner_threshold_deg, profile.drag_arc_step_deg});
      if (compensated.points_mm.size() >= 2) adapted.push_back(std::move(compensated));
    } else if (tool.kind == ToolKind::TangentialKnife) {
      for (Stroke& part : split_for_tangential_knife(stroke, profile.corner_threshold_deg, knife_angle_deg)) {
        adapted.push_back(std::move(part));
      }
    } else {
      adapted.push_back(stroke);
    }
  }
  return adapted;
}

}  // namespace

CutProgram plan_cut_program(const std::vector<PlacedPiece>& pieces, const MachineProfile& profile, PieceOrder order) {
  std::vector<PlacedPiece> clean;
  clean.reserve(pieces.size());
  for (size_t i = 0; i < pieces.size(); ++i) clean.push_back(checked_piece(pieces[i], i, profile));

  // Where the tool arrives at a piece (its label, else its first mark) and where it leaves it
  // (the contour start). The label is measured with the widest order number it can get.
  std::vector<Point2> entries, exits;
  const int widest_order = static_cast<int>(std::pow(10.0, std::floor(std::log10(std::max<double>(1, clean.size())))) * 10 - 1);
  for (const PlacedPiece& piece : clean) {
    exits.push_back(tour_stop(piece.outline));
    std::optional<PlacedText> label;
    if (profile.label.enabled && profile.pen) {
      label = place_text(piece_marking(widest_order, piece.label), piece.outline, profile.label.height_mm,
                         profile.label.min_height_mm);
    }
    const bool draws_lines = profile.pen && !piece.drawn_lines_mm.empty();
    entries.push_back(label          ? label->center_mm
                      : draws_lines ? piece.drawn_lines_mm.front().front()
                      : piece.marks.empty() ? exits.back()
                                            : piece.marks.front().from_mm);
  }
  std::vector<int> sequence(clean.size());
  std::iota(sequence.begin(), sequence.end(), 0);
  if (order == PieceOrder::ShortTravel) sequence = order_for_short_travel(entries, exits, Point2::Zero());
  if (order == PieceOrder::NearestNeighbour) sequence = order_by_nearest_neighbour(entries, exits, Point2::Zero());

  CutProgram program;
  program.work_area_x_mm = profile.work_area_x_mm;
  program.work_area_y_mm = profile.work_area_y_mm;
  Point2 tool_mm = Point2::Zero();
  for (size_t k = 0; k < sequence.size(); ++k) {
    add_piece_strokes(clean[sequence[k]], static_cast<int>(k), profile, tool_mm, program);
  }
  program.tip_strokes = program.strokes;
  program.strokes = adapt_to_tools(program.tip_strokes, profile);
  return program;
}

}  // namespace lastcut
