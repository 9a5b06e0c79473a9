#pragma once
// An ejection chain that empties one hide in one go: every unit (piece or pair group) of the target
// hide is taken off and dealt to the other hides allowed (the most free area left first, largest
// unit first); on each receiving hide the units take a free sampled spot when there is one and are
// otherwise dropped in at a random pose, overlapping, and the hide is separated by guided local
// search. What cannot be separated is ejected: while overlap is left, the unit with the most overlap
// per mm^2 of its own area leaves the hide (so small pieces make room for large ones), and the
// ejected units are dealt again, to any hide but the one they just left, up to a depth. The chain
// succeeds only when the target hide is empty and every hide is feasible; the caller keeps a copy
// to restore otherwise. With an unused smaller hide among the destinations the same chain replaces
// a big hide by a smaller one (same hide count, less leather).
// This is the strip search's "shrink the strip and separate" (Egeblad, Nielsen & Odgaard, "Fast
// neighborhood search for two- and three-dimensional nesting problems", EJOR 183, 2007; Umetani,
// Yagiura, Imahori, Imamichi, Nonobe & Ibaraki, "Solving the irregular strip packing problem via
// guided local search for overlap minimization", ITOR 16, 2009) turned into "remove a hide and
// separate", with the ejection of the bin-packing local searches that empty a bin: Lodi, Martello &
// Vigo, "Heuristic and metaheuristic approaches for a class of two-dimensional bin packing problems",
// INFORMS Journal on Computing 11, 1999 (tabu search emptying the weakest bin), and ejection chains
// after Glover, "Ejection chains, reference structures and alternating path methods for traveling
// salesman problems", Discrete Applied Mathematics 65, 1996.
// Deterministic for the seed and sweep workers; the deadline only stops it (then it fails).
#include <cstdint>
#include <vector>

#include "engine/nest/hide_pieces.hpp"
#include "engine/nest/nest_options.hpp"

namespace lastcut::nest_detail {

struct EjectBudget {
  int strikes = 2;    // separation strikes per receiving hide (engine/nest/parallel_separation)
  int stale = 15;     // sweeps without a 2 % improvement that make a strike
  int destinations = 3;    // hides one unit tries, most free area first
  int max_ejections = 6;   // insertions beyond the target's own units before the chain gives up
};

// slot_of, state: per piece (slot_of -1 = not placed), changed in place (a partial result when it
// fails: the caller drops it). target: the hide to empty; destinations: the hides that may receive
// (never the target). The pair rule holds on every hide that received units.
bool eject_hide(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options,
                const Deadline& deadline, std::vector<int>& slot_of, std::vector<PieceState>& state, int target,
                const std::vector<int>& destinations, std::uint64_t seed, const EjectBudget& budget);

}  // namespace lastcut::nest_detail
