#pragma once
// plan_cut_program: placed pieces -> the ordered strokes a machine performs.
//   1. every piece is checked (finite, >= 3 points, non-zero area, inside the work area),
//   2. each piece gets its contour start (a corner, see piece_contour.hpp),
//   3. pieces are ordered for short travel (travel_order.hpp) or kept in layout order,
//   4. per piece, in this order: its label with the pen (piece_label.hpp), its drawn lines with the
//      pen (nearest first; left out when the profile has no pen, never cut), its marks with the
//      mark tool (nearest first; notches as the profile's [notch] says, mark_stroke.hpp), then the
//      contour with the knife, closed with an overcut. Marks, lines and labels come first because a
//      piece cut free may shift on the table,
//   5. every stroke is adapted to its tool: drag-knife offset compensation (drag_knife.hpp) or
//      tangential-knife angles with lift-rotate-plunge (tangential_knife.hpp).
#include <vector>

#include "engine/toolpath/cut_program.hpp"
#include "engine/toolpath/machine_profile.hpp"
#include "engine/toolpath/placed_piece.hpp"

namespace lastcut {

enum class PieceOrder {
  ShortTravel,  // nearest neighbour + 2-opt + Or-opt
  AsGiven,      // the order of `pieces` (the layout's own order), for comparison
  NearestNeighbour,  // nearest neighbour alone, for comparison
};

// Throws EngineError (one line naming the piece) when a piece is degenerate, not finite or lies
// outside the profile's work area.
CutProgram plan_cut_program(const std::vector<PlacedPiece>& pieces, const MachineProfile& profile,
                            PieceOrder order = PieceOrder::ShortTravel);

}  // namespace lastcut
