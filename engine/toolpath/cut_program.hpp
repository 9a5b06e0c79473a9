#pragma once
// CutProgram: what a cutting machine does with a layout, independent of the file format.
// A program is an ordered list of strokes; between two strokes the tool is up and travels in a
// straight line. The writers (HPGL, G-code, DXF, SVG) only translate strokes into their syntax.
#include <string>
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

// The three operations a cutter head performs. Each maps to one tool of the machine profile.
enum class ToolRole {
  Cut,   // the knife following a piece's outline
  Mark,  // notches and landmarks (a pen, a notch knife or the cutting knife)
  Pen,   // the label of a piece (single-stroke lettering) and the lines drawn on it
};

std::string to_string(ToolRole role);

// One tool-down movement. points_mm #P (>= 2) is the path of the tool's reference point
// (for a compensated drag knife: the holder axis, not the blade tip). knife_angle_deg is empty
// unless the tool is a tangential knife; then it has #P entries: the blade direction (degrees,
// CCW from +X, unwrapped so that consecutive values never jump by 360) reached at each point.
// Two equal consecutive points with different angles are a rotation in place, knife down.
struct Stroke {
  ToolRole tool = ToolRole::Cut;
  std::vector<Point2> points_mm;
  std::vector<double> knife_angle_deg;
  int piece = -1;             // index into CutProgram::pieces, -1 for none
  bool closed_outline = false;  // part of the outline of its piece (the contour cut)
};

// What the operator needs to find a piece on the table: its place in the cutting order.
struct ProgramPiece {
  int item_id = -1;
  std::string label;   // the item's label from the layout
  std::string marking; // the text drawn on it ("3 42 L"), empty when no label was drawn
  Polygon2 outline_mm; // the placed outline (CCW), first point = where its contour cut starts
};

struct CutProgram {
  std::vector<Stroke> strokes;       // in cutting order, what the tool axis does
  std::vector<Stroke> tip_strokes;   // the same before knife compensation: what the blade tip or
                                     // pen draws on the material (DXF and SVG show these)
  std::vector<ProgramPiece> pieces;  // in cutting order
  // Lines naming what the program carries ("lastcut batch B", "lastcut job J"), written as comments
  // at the top where the format has comments (G-code), so the machine's own log shows which jobs it cut.
  std::vector<std::string> notes;
  double work_area_x_mm = 0.0;       // the machine's table, for writers that draw a frame
  double work_area_y_mm = 0.0;
};

// Lengths summed over a program: cut_length_mm is tool-down path length of Cut strokes,
// mark_length_mm of Mark and Pen strokes, travel_length_mm is tool-up travel starting and
// ending at the machine origin (0, 0), tool_lifts counts every tool-up (one per stroke).
struct CutStats {
  double cut_length_mm = 0.0;
  double mark_length_mm = 0.0;
  double travel_length_mm = 0.0;
  int tool_lifts = 0;
  int strokes = 0;
};

CutStats measure_program(const CutProgram& program);

// Length of an open polyline (mm).
double polyline_length(const std::vector<Point2>& points_mm);

}  // namespace lastcut
