#pragma once
// Greedy construction on hides, shared by both hide methods: hides in their opening order
// (HidePieces::slots), units (single pieces and pair groups) in the given order, each piece at the
// sampled feasible spot (exact test against the hide outline, defects and forbidden quality zones)
// minimising its right edge, refined by sliding; the other pieces of a pair group as near the first
// one as the samples allow. A unit goes onto the first hide where all of its pieces fit near each other.
#include <cstdint>
#include <vector>

#include "engine/nest/hide_pieces.hpp"
#include "engine/nest/nest_random.hpp"

namespace lastcut::nest_detail {

struct HideAssignment {
  std::vector<int> slot_of;        // per piece; -1 = not placed
  std::vector<PieceState> state;   // per piece, in its slot's frame
  double placed_area = 0;          // mm^2
  int slots_used = 0;
  double spread = 0;  // sum of the pieces' right edges relative to their hide: smaller = more compact
  // By area placed, then hides used, then compactness.
  bool better_than(const HideAssignment& o) const;
};

// unit_order: indices into pieces.units.
HideAssignment greedy_hides(const NestInstance& instance, const HidePieces& pieces, const std::vector<int>& unit_order,
                            std::uint64_t seed);

// Units by priority (highest first), then area (largest first).
std::vector<int> unit_order_by_value(const HidePieces& pieces);

// `units` in a perturbed largest-first order (the iterated greedy's restart, Ruiz & Stuetzle 2007):
// each unit's area times a random factor in [1, 1.6), the factors drawn from `random` in the order of
// `units`; with priorities_first, a higher priority first whatever the areas.
std::vector<int> perturbed_order(const HidePieces& pieces, std::vector<int> units, Random& random, bool priorities_first);

}  // namespace lastcut::nest_detail
