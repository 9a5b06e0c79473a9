#pragma once
// The hide search's state: which hide each piece lies on and where (a HidePlacement), with what the
// moves ask of it all the time (the area placed on each hide, cached, and what follows from it: fill,
// free area, concentration) and the search's objective as one comparison. The moves change the
// placement in place, by take_off or through edit(); the cache is refreshed at the next read.
#include <cstddef>
#include <vector>

#include "engine/nest/hide_pieces.hpp"

namespace lastcut::nest_detail {

class HideSearchState {
 public:
  HideSearchState(const HidePieces& pieces, HidePlacement placement);

  const HidePlacement& placement() const { return placement_; }
  // For the algorithms that change the placement in place (eject, merge, re-pack, free placement):
  // the cached areas are recomputed at the next read.
  HidePlacement& edit() {
    stale_ = true;
    return placement_;
  }
  const std::vector<int>& slot_of() const { return placement_.slot_of; }
  const std::vector<PieceState>& state() const { return placement_.state; }
  // The unit's pieces leave their hide (slot -1).
  void take_off(int unit);

  double usable_area_mm2(int slot) const;
  double placed_area_mm2(int slot) const;
  double free_area_mm2(int slot) const { return usable_area_mm2(slot) - placed_area_mm2(slot); }
  double fill(int slot) const { return placed_area_mm2(slot) / usable_area_mm2(slot); }
  // The hides holding a piece, in slot order.
  std::vector<int> used_slots() const;
  // The used hides, the one to empty first first: least filled, then the smallest.
  std::vector<int> targets() const;
  // The units on `slot`, largest first.
  std::vector<int> units_on(int slot) const;
  // The fewest hides whose usable areas could hold the placed pieces (hide_area_bound).
  size_t area_bound() const;
  bool any_left_over() const;  // a piece on no hide
  // Sum over hides of placed area x fill (mm^2, hide_repack's concentration): grows when area moves
  // from a less filled hide to a fuller one.
  double concentration() const;

  // The search's objective: more placed area, then fewer hides, then less leather (the usable area
  // of the used hides), then more concentrated.
  bool better_than(const HideSearchState& other) const;

 private:
  void refresh() const;

  const HidePieces* pieces_;
  HidePlacement placement_;
  mutable bool stale_ = true;
  mutable std::vector<double> placed_mm2_;  // per hide, summed in piece order (as placed_area_mm2)
  mutable std::vector<char> used_;          // per hide: holds a piece
  mutable double total_placed_mm2_ = 0;     // summed in piece order
};

}  // namespace lastcut::nest_detail
