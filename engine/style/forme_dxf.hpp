#pragma once
// The forme a pattern maker draws a style on (issue 34, point 1), as an R12 DXF in mm that any CAD
// program opens (LibreCAD, AutoCAD, pattern CAD): both halves of the reference last laid over each other
// (forme_layout.hpp), each on its own layer, and the layers the pattern maker draws on left empty.
//   LATERAL, MEDIAL   each half's whole outline (closed polyline)
//   FEATHER, TOP      both halves' feather lines and top edges
//   CENTRE            both halves' front and back seams (the centre line)
//   LANDMARKS         a POINT and a TEXT ("lateral toe", ...) at toe, heel, top_front and top_back of each half
//   PIECES            empty: one TEXT per piece, inside it (forme_drawing.hpp)
//   LINE-example      empty: a style line goes on a layer LINE-<name>
//   0                 a short note below the forme on how to draw
// The layers' names are what read_forme_drawing and docs/style-authoring.md expect.
#include <string>

#include "engine/style/forme_layout.hpp"

namespace lastcut {

// The whole file.
std::string forme_dxf(const FormeLayout& layout);

}  // namespace lastcut
