#pragma once
// Re-packing a few hides from scratch: the units now on them are taken off and placed again, greedily,
// in a given order, each onto the first of the hides (in the given order) where all its pieces find a
// free sampled spot near each other. With the fullest hide first and the units in a perturbed
// largest-first order it is the iterated greedy (engine/nest/hide_greedy) on a small neighbourhood: it
// fills one hide tighter and leaves another emptier without any separation, which makes it cheap
// next to the hide search's insertions. Deterministic for the seed.
// Iterated greedy: Ruiz & Stuetzle, "A simple and effective iterated greedy algorithm for the
// permutation flowshop scheduling problem", European Journal of Operational Research 177, 2007.
// The concentration measure follows the bin-packing fitness of Falkenauer & Delchambre, "A genetic
// algorithm for bin packing and line balancing", IEEE ICRA 1992 (sum of fill^2, here weighted by area).
#include <cstdint>
#include <vector>

#include "engine/nest/hide_pieces.hpp"

namespace lastcut::nest_detail {

// slot_of, state: per piece (slot_of -1 = not placed), changed in place. slots: the hides to fill, in
// order; units: every unit to place, in order (their pieces are taken off first). False when some
// unit found no place (slot_of/state then hold a partial assignment: the caller drops it).
bool repack_hides(const NestInstance& instance, const HidePieces& pieces, std::vector<int>& slot_of,
                  std::vector<PieceState>& state, const std::vector<int>& slots, const std::vector<int>& units,
                  std::uint64_t seed);

// Sum over hides of placed area x fill (mm^2): grows when area moves from a less filled hide to a
// fuller one; the search keeps only moves that raise it, so it cannot cycle.
double concentration(const HidePieces& pieces, const std::vector<int>& slot_of);

}  // namespace lastcut::nest_detail
