#pragma once
// What both hide nesters (greedy, search) work on: every copy of every item as a piece, prepared once
// per grain frame (a hide with a backbone turns the allowed poses of pieces with a grain), the pieces
// grouped into units that go onto one hide together (a pair group: the left and right molds of one
// order), and the hides as containers in the order they are opened. Also the pair rule ("near") and
// turning a piece-to-hide assignment into a Layout.
#include <memory>
#include <string>
#include <vector>

#include "engine/nest/hide_container.hpp"
#include "engine/nest/layout.hpp"
#include "engine/nest/nest_options.hpp"
#include "engine/nest/separator.hpp"

namespace lastcut::nest_detail {

struct HideSlot {  // one copy of one bin
  int bin_index = 0;
  int copy = 0;
  int frame = 0;  // index into HidePieces::frames
  std::unique_ptr<HideContainer> container;
};

struct HidePieces {
  std::vector<std::vector<PreparedItem>> frames;  // per distinct backbone: every item, poses turned to it
  std::vector<int> item_of;                       // per piece: index into NestInstance::items
  std::vector<int> unit_of;                       // per piece: index into units
  std::vector<std::vector<int>> units;            // pieces that share a hide (a pair group, or one piece)
  std::vector<std::string> unit_group;            // per unit: the pair group ("" for a single piece)
  std::vector<double> unit_area_mm2;
  std::vector<int> unit_priority;                 // highest priority of its items
  std::vector<Point2> centroid;                   // per item, own frame (mm)
  std::vector<double> diagonal_mm;                // per item: bounding box diagonal of the exact shape
  std::vector<HideSlot> slots;                    // cheapest per usable area first, largest on a tie
  std::vector<Unplaced> unplaced;                 // items with no allowed pose on any hide
  double gap_mm = 0, pair_distance_mm = 0;

  const PreparedItem& prepared(int piece, int slot) const { return frames[slots[slot].frame][item_of[piece]]; }
  bool fits_frame(int piece, int slot) const { return !prepared(piece, slot).orientations.empty(); }
  // Where the piece's centroid lands in the given state on that slot (mm).
  Point2 placed_centroid(int piece, int slot, const PieceState& state) const;
};

HidePieces prepare_hide_pieces(const NestInstance& instance, const NestOptions& options);

// Which hide each piece lies on, and where.
struct HidePlacement {
  std::vector<int> slot_of;        // per piece; -1 = not placed
  std::vector<PieceState> state;   // per piece, in its slot's frame
};

// The pair rule, shared with the checker's documentation: two pieces of one group are near when
// their centroids are at most pair_distance_mm apart (instance value when > 0, otherwise the mean
// of their bounding box diagonals plus the gap). A group is near when every piece has another
// piece of the group near it.
double pair_bound_mm(const NestInstance& instance, double gap_mm, const NestItem& a, const NestItem& b);
// Whether the unit's pieces, all on `slot` in `state` (per piece), are near each other.
bool unit_near(const HidePieces& pieces, const NestInstance& instance, int unit, int slot,
               const std::vector<PieceState>& state);

// The fewest hides whose usable areas, largest first, cover the placed area of slot_of (per piece,
// -1 = not placed): no hide search move goes below it.
size_t hide_area_bound(const HidePieces& pieces, const std::vector<int>& slot_of);

// The layout of an assignment: slot_of per piece (-1: not placed), state per piece in its slot's frame.
Layout hide_layout(const NestInstance& instance, const HidePieces& pieces, const std::vector<int>& slot_of,
                   const std::vector<PieceState>& state, std::vector<Unplaced> unplaced);

// hide_layout with the pieces not placed listed per item: with_reasons = the reason found by
// unplaced_reason (slow), otherwise "no room found yet" (the layouts reported while searching).
Layout finish_hides(const NestInstance& instance, const HidePieces& pieces, const std::vector<int>& slot_of,
                    const std::vector<PieceState>& state, bool with_reasons, std::uint64_t seed);

// Why a unit stayed off the hides: it fits an empty hide (then the hides ran out) or none at all.
std::string unplaced_reason(const HidePieces& pieces, int unit, std::uint64_t seed);

// The feasible sampled spot minimising `objective` for `piece` on `slot` among the `active` pieces
// (slot_of == slot and active), refined by sliding; false when none was found.
bool place_on_slot(const HidePieces& pieces, int piece, int slot, std::vector<int>& slot_of,
                   std::vector<PieceState>& state, const Separator::Objective& objective, int samples,
                   std::uint64_t seed);

// Area of the pieces on `slot` in slot_of (per piece), mm^2.
double placed_area_mm2(const HidePieces& pieces, const std::vector<int>& slot_of, int slot);
// Usable area of `slot` not taken by the pieces on it in slot_of (per piece), mm^2.
double free_area_mm2(const HidePieces& pieces, const std::vector<int>& slot_of, int slot);

// place_on_slot's objective for a pair member: the distance of its box centre to that of `first`
// where it lies on `slot` (first_state), so the member goes next to its first piece.
Separator::Objective near_piece(const HidePieces& pieces, int first, int slot, const PieceState& first_state);

// Every piece of `unit` at a free sampled spot of `slot`: the first as far left (then low) as the
// samples allow, the others near it. True when each found a spot and the unit is near; otherwise the
// pieces placed so far stay placed (the caller undoes them).
bool place_unit_free(const HidePieces& pieces, const NestInstance& instance, int unit, int slot, std::vector<int>& slot_of,
                     std::vector<PieceState>& state, int samples, std::uint64_t seed);

}  // namespace lastcut::nest_detail
