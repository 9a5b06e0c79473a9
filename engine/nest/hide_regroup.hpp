#pragma once
// The placed units regrouped onto fewer hides, decided hide by hide: which units go onto which hide is
// searched as a bin-packing assignment, and whether one hide can hold its units is asked of the hide
// search itself on that hide alone (an oracle with a short budget). The moves of the hide search
// carry one unit at a time between packed hides and stall where the pieces are large next to the
// hides (Baldacci Test6: pieces of a quarter of a hide); deciding the grouping first and the packing
// per hide afterwards reaches the groupings one unit at a time cannot (docs/benchmarks-nest.md).
//
// Start: units by area, largest first, each onto the target hide whose fill by area would stay lowest
// (worst fit by fill). Then, while a hide cannot hold its units (the oracle leaves some over), that hide
// is asked once more, four times as long (a short question can miss a packing), and then one of its
// left-over units u:
//   - move: onto the least filled other hide that can hold it with its own units;
//   - swap: for a smaller unit v of another hide, when that hide holds its units with u instead of v
//     and the first hide then leaves less area over than u's;
//   - otherwise a kick: a random unit of the hide onto a random other hide.
// Bin packing with a packing oracle per bin: the assignment view of two-dimensional bin packing
// (Lodi, Martello & Vigo, "Recent advances on two-dimensional bin packing problems", Discrete Applied
// Mathematics 123, 2002) with worst-fit decreasing as the start (Johnson, "Fast algorithms for bin
// packing", JCSS 8, 1974) and the swap neighbourhood of Fleszar & Hindi's variable neighbourhood
// search for bin packing (Computers & Operations Research 29, 2002).
// Oracle answers are cached per (hide, units), and a hide is not asked for a superset of units it
// could not hold. Deterministic for the seed when the oracle runs on a
// round budget (NestOptions::iteration_limit set); otherwise its time budget decides its answers.
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "engine/nest/hide_pieces.hpp"
#include "engine/nest/nest_random.hpp"

namespace lastcut::nest_detail {

struct RegroupBudget {
  double oracle_s = 0.3;      // time of one oracle search (time mode)
  long oracle_rounds = 40;    // rounds of one oracle search (round mode: options.iteration_limit set)
  long most_oracle_calls = 400;
};

// The best placement of an instance with one hide (one bin, stock 1), `pieces` prepared from it: the
// hide search on that hide alone, handed in by the search (this file does not call it by name).
using HidePackingOracle = std::function<HidePlacement(const NestInstance&, const HidePieces&, const NestOptions&)>;

// Every unit placed in `placed` (units left over stay so) onto `target_slots`, each hide packed by
// `oracle` alone; nullopt when no grouping was found before `deadline` or the call budget.
std::optional<HidePlacement> regroup_onto(const NestInstance& instance, const HidePieces& pieces,
                                          const NestOptions& options, const std::vector<int>& placed_slot_of,
                                          const std::vector<int>& target_slots, const Deadline& deadline,
                                          const RegroupBudget& budget, std::uint64_t seed, const HidePackingOracle& oracle);

}  // namespace lastcut::nest_detail
