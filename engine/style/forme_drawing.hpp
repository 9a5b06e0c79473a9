#pragma once
// A style as a pattern maker draws it on the forme DXF that `lastcut style new` writes (issue 34,
// point 1), read into plain 2D data. The rules (docs/style-authoring.md):
//   - each style line on a layer of its own: LINE-<name> for a line on both halves (the forme shows them
//     overlaid), LINE-medial-<name> or LINE-lateral-<name> for a line on one half; the name is letters,
//     digits, '-' and '_' (what an R12 layer name holds);
//   - a line is LINEs chained end to end, POLYLINEs or LWPOLYLINEs (bulges flattened) and ARCs, in any
//     order and direction, as long as they join end to end into one open or closed line;
//   - each piece is named by a TEXT (or MTEXT) on layer PIECES whose insertion point lies inside the
//     piece; a text "medial ..." labels a piece on the medial half, any other the lateral half.
// Refused in one line naming the file and the line or text: a layer LINE- without a name or with other
// characters, an entity on a line layer that is not read (a SPLINE, a CIRCLE: draw it as a polyline), a
// line in parts that do not join or that branches, a line drawn both for both halves and for one, an
// empty piece text, two texts naming one piece.
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

inline constexpr char kFormePiecesLayer[] = "PIECES";
inline constexpr char kFormeLinePrefix[] = "LINE-";

enum class FormeHalves { Both, Medial, Lateral };

struct FormeLineDrawing {
  std::string name;                 // after LINE-, LINE-medial- or LINE-lateral-, as written
  std::string layer;                // as written, for messages
  FormeHalves halves = FormeHalves::Both;
  std::vector<Point2> points_mm;    // >= 2, end to end; a closed line repeats its first point last
};

struct FormePieceText {
  std::string name;                 // the text as written (trimmed): the piece's name
  FormeHalves half = FormeHalves::Lateral;  // Medial when the text begins with "medial "
  Point2 at_mm = Point2::Zero();    // the text's insertion point
};

struct FormeDrawing {
  std::string source;               // the file, named in every refusal
  std::vector<FormeLineDrawing> lines;   // in the order of their first entity in the file
  std::vector<FormePieceText> pieces;    // in the file's order
};

// Throws EngineError (one line, naming the file) as above, and when the file is no DXF or has no piece text.
FormeDrawing read_forme_drawing(const std::filesystem::path& dxf);

// "(x, y)" in mm with one decimal, as refusals give forme points.
std::string forme_point_text(const Point2& at_mm);

}  // namespace lastcut
