#pragma once
// An ejection chain that empties one hide in one go: every unit (piece or pair group) of the target
// hide is taken off, and the units, largest first, are inserted into the other hides allowed: at a
// free sampled spot on any of them when there is one, otherwise dropped in at a random pose,
// overlapping, on each of the few with the most free area in turn, and that hide separated by guided
// local search. What a separation leaves overlapping is ejected: while overlap is left, the unit with
// the most overlap per mm^2 of its own area leaves the hide (so small pieces make room for large
// ones; units this chain has moved only as a last resort). Of the hides tried, the one that ejects
// the least area (bounded by a multiple of the inserted unit's) is kept, and the ejected units are
// inserted the same way, never back onto a hide they left, up to a number of insertions. The target
// counts as emptied only when no unit is left over and every hide is feasible; a chain that stops
// before puts what is left back onto the target at free spots (a rearrangement the caller may keep),
// and the caller restores its copy otherwise. With an unused smaller hide among the destinations the
// same chain replaces a big hide by a smaller one (same hide count, less leather).
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
  int destinations = 3;      // hides one unit is separated on, most free area first
  int max_ejections = 8;     // insertions beyond the target's own units before the chain stops
  double eject_ratio = 1.5;  // a unit may eject at most this times its own area (measured: 1.0 is too strict
                             // for Test6's pieces of a quarter hide, docs/benchmarks-nest.md)
};

// Which hide the `turn`-th chain tries to empty and where its units may go. order: the used hides,
// the one to empty first first (the least filled); the turns go round them, because with hides of
// different sizes the least filled is not always the one that can go. On every other round (every
// round when replace_only: the used hides are as few as their area allows) an unused hide smaller
// than the target and no dearer joins the destinations, the smaller hides in turn, largest first:
// the same hide count on less leather. target = -1 when that turn has no such hide.
struct EjectTurn {
  int target = -1;
  std::vector<int> destinations;
};
EjectTurn eject_turn(const NestInstance& instance, const HidePieces& pieces, const std::vector<int>& order, long turn,
                     bool replace_only);

// Emptied: the target holds nothing. Rearranged: the chain stopped before (out of steps, or a unit
// found no hide), and the units left over went back onto the target at free spots: every hide is
// feasible, some of the target's units now lie elsewhere (the caller keeps it only when the hides
// got fuller, engine/nest/hide_repack's concentration). Failed: not even that.
enum class EjectResult { Failed, Rearranged, Emptied };

// slot_of, state: per piece (slot_of -1 = not placed), changed in place (a partial result when it
// fails: the caller drops it). target: the hide to empty; destinations: the hides that may receive
// (never the target). The pair rule holds on every hide that received units.
EjectResult eject_hide(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options,
                const Deadline& deadline, std::vector<int>& slot_of, std::vector<PieceState>& state, int target,
                const std::vector<int>& destinations, std::uint64_t seed, const EjectBudget& budget);

}  // namespace lastcut::nest_detail
