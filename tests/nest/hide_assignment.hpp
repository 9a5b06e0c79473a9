#pragma once
// Hand-placed hide layouts for the tests of the hide search's moves (hide_eject, hide_merge): which
// hide each piece lies on, and where.
#include <vector>

#include "engine/nest/hide_pieces.hpp"
#include "engine/nest/nest_geometry.hpp"
#include "nest_test_instances.hpp"

namespace lastcut::test {

struct HideAssignment {
  std::vector<int> slot_of;                   // per piece: the hide slot, -1 when not placed
  std::vector<nest_detail::PieceState> state;  // per piece: its pose and position
};

// Puts `piece` on `slot` at the feasible sampled spot whose box centre is nearest (x, y) mm.
inline bool put(const nest_detail::HidePieces& pieces, HideAssignment& a, int piece, int slot, double x, double y) {
  const Point2 want(x, y);
  const auto distance_to_want = [want](const nest_detail::Box& b) {
    return (Point2(0.5 * (b.x0 + b.x1), 0.5 * (b.y0 + b.y1)) - want).norm();
  };
  return nest_detail::place_on_slot(pieces, piece, slot, a.slot_of, a.state, distance_to_want, 2000, 7);
}

// `hides` square hides of side_mm, with the given gap and margin and no items yet.
inline NestInstance square_hides(int hides, double side_mm, double gap_mm, double margin_mm) {
  NestInstance instance;
  instance.name = "square hides";
  for (int h = 0; h < hides; ++h) {
    Bin bin;
    bin.id = h + 1;
    bin.outer = rectangle(side_mm, side_mm);
    instance.bins.push_back(bin);
  }
  instance.gap_mm = gap_mm;
  instance.margin_mm = margin_mm;
  return instance;
}

inline int pieces_on(const HideAssignment& a, int slot) {
  int n = 0;
  for (int s : a.slot_of) n += s == slot ? 1 : 0;
  return n;
}

}  // namespace lastcut::test
