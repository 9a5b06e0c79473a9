#pragma once
// A style drawn on the forme (forme_drawing.hpp) lifted onto the reference last (issue 34, point 1): the
// same style lines and piece labels a style drawn in 3D (lines.obj, [[piece]] label) gives, so the rest
// of the style's way (transfer, regions, pieces) does not know how it was drawn.
//
// A forme point is found in a half's triangles as laid on the forme (forme_layout.hpp; barycentric,
// triangle_locator.hpp) and lifted to the same barycentric point of that half's 3D mesh. Lines are
// sampled every millimetre on the forme first, so the lifted line follows the last's surface. Per half,
// forme_half_runs.hpp cuts each line to the half and settles its ends. Then:
//   - a line for both halves (and a LINE-medial-X with its LINE-lateral-X) is one 3D line: its lateral
//     and medial runs are joined where both end on the same centre seam within kFormeJoinGap_mm of each
//     other (measured along the seam on the last), at the seam's point halfway between them; a line
//     touching the centre line at both ends closes on itself. Runs that do not meet stay lines of their
//     own under the same name;
//   - an end on the feather line or the top edge is put on the last's outline and 1e-4 mm past it, so
//     the transfer (style_transfer.hpp) reads it as a point of that edge and lands it on the new last's.
// Piece texts: a text "medial ..." is lifted on the medial half, any other on the lateral half; it must
// lie inside that half on the forme.
#include <Eigen/Geometry>
#include <vector>

#include "engine/style/forme_drawing.hpp"
#include "engine/style/forme_layout.hpp"
#include "engine/style/style_definition.hpp"

namespace lastcut {

// The halves' centre lines lie up to 7.7 mm apart on the forme (generated EU 42, forme_layout.hpp), so a
// line drawn once reaches the two seams at points that far apart along the last's seam.
inline constexpr double kFormeJoinGap_mm = 10.0;

struct LiftedForme {
  std::vector<StyleLine> lines;    // in the reference scan's frame (mm); a line's separate parts share its name
  std::vector<StylePiece> pieces;  // name and label_mm (reference scan's frame); material and quantity left at their defaults
};

// layout: forme_layout of the reference the drawing was made on; scan_to_canonical: that reference's
// (ScanResult::scan_to_canonical). Throws EngineError (one line naming the file, the line or text, and
// forme coordinates): a line more than 2 mm outside the forme, a line end inside the upper, a piece text
// outside its half.
LiftedForme lift_forme_drawing(const FormeDrawing& drawing, const FormeLayout& layout, const Eigen::Affine3d& scan_to_canonical);

}  // namespace lastcut
