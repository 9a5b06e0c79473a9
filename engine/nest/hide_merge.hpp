#pragma once
// Two used hides replaced by one unused one: the search's other moves never open a hide, so a layout
// whose small hides are in use while a larger one lies unused cannot reach the fewer, larger hides
// (Baldacci Test5 at 9 hides: 51.6 and 58.9 area units in use at 55-57 % fill, a 59.5 one unused;
// the eight largest hides hold the pieces at 70.7 %, docs/benchmarks-nest.md). The merge empties
// both, one after the other, by the ejection chain of engine/nest/hide_eject with the unused hide
// among the destinations: its empty area takes the first hide's pieces at free spots, and the
// second hide's are separated into it and the others. It counts only when both are empty (one hide
// fewer); the caller drops anything less.
// This is the bin-packing local search that empties the weakest bins by re-packing a few bins
// together (Lodi, Martello & Vigo, "Heuristic and metaheuristic approaches for a class of
// two-dimensional bin packing problems", INFORMS Journal on Computing 11, 1999: the target bin
// joined by k others), with the choice of the bins from the variable-sized bin-packing view that the
// best set of hides is the fewest that cover the pieces (Baldacci, Boschetti, Ganovelli & Maniezzo,
// "Algorithms for nesting with defects", Discrete Applied Mathematics 163, 2014), and the chain of
// Glover, "Ejection chains, reference structures and alternating path methods for traveling
// salesman problems", Discrete Applied Mathematics 65, 1996.
// Deterministic for the seed and sweep workers; the deadline only stops it.
#include <cstdint>
#include <vector>

#include "engine/nest/hide_eject.hpp"

namespace lastcut::nest_detail {

// Which two hides the `turn`-th merge empties and which unused hide joins the others.
// order: the used hides. Candidates: every pair of used hides with the largest unused hide no
// dearer than the two together, kept when the fill of the hides left, by area, is at most max_fill;
// the lowest such fill first (the turns go round them). first is the hide with less placed area.
// first = -1 when no pair qualifies.
struct MergeTurn {
  int first = -1, second = -1, spare = -1;
  double fill_after = 0;  // placed area over the usable area of the hides left (0..1)
  std::vector<int> destinations;  // the used hides but the two, then the spare
};
MergeTurn merge_turn(const NestInstance& instance, const HidePieces& pieces, const std::vector<int>& slot_of,
                     const std::vector<int>& order, long turn, double max_fill);

// Empties turn.first, then turn.second, into turn.destinations (slot_of, state per piece, changed in
// place; a partial result when it fails: the caller restores its copy). True when both are empty.
bool merge_hides(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options, const Deadline& deadline,
                 std::vector<int>& slot_of, std::vector<PieceState>& state, const MergeTurn& turn, std::uint64_t seed,
                 const EjectBudget& budget);

}  // namespace lastcut::nest_detail
