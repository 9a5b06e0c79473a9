#pragma once
// The hide search: the strip nester's overlap-minimising machinery (separation by guided local
// search, sparrow's sampled placement + coordinate descent, the pole overlap proxy, parallel sweep
// workers) inside irregular containers (engine/nest/hide_container: outline inset by the margin,
// defects grown by it, zones too poor for a piece or one of its quality regions forbidden, all with a
// smooth pole penalty). Method: sparrow (Gardeyn, Vanden Berghe & Wauters, arXiv:2509.13329, 2025),
// guided local search for nesting (Egeblad, Nielsen & Odgaard 2007), applied to the leather problem
// of Baldacci, Boschetti, Ganovelli & Maniezzo (Discrete Applied Mathematics 163, 2014).
//
// Start: the greedy of engine/nest/hide_greedy (units by priority, then area; hides largest usable
// area first). Then rounds, each one move that is kept only when it ends feasible. The state is
// engine/nest/hide_search_state (its better_than is the objective), each move is a file of its own
// (engine/nest/hide_moves.hpp lists them), which move runs on which attempt is the table of
// engine/nest/hide_schedule, and the tuning constants are engine/nest/hide_search_tuning.hpp:
// - insert: a unit left over (highest value first) goes onto one of the two used hides with the most
//   free area, else one of the first two unopened hides (opening order): at a free sampled spot if there is one,
//   otherwise dropped in and the hide separated. A unit that fails is not tried again until a hide
//   has been closed (knapsack form).
// - move: one unit of a little-filled hide (the least filled first, the smaller hide on a tie; after
//   per_target failed attempts the next hide) goes, by the same insertion, onto a hide at least as full.
// - chain (every other attempt, at every level): an ejection chain (engine/nest/hide_eject) empties a
//   used hide as a whole, the used hides in turn, least filled first, into the others by separation,
//   ejecting what cannot be separated; on every other round an unused smaller hide joins the
//   destinations (a big hide replaced by a smaller one). Kept when the hide is empty, or when the
//   chain stopped early and put the rest back but the hides got more concentrated. Every third chain
//   is a merge (engine/nest/hide_merge): two used hides emptied into the others plus the largest
//   unused hide, when the hides left could hold the pieces by area (one hide fewer, fewer larger hides).
// Once a whole cycle over the used hides failed (effort level 1), every fourth of the other attempts
// is a move and the others are:
// - swap: one unit of a little-filled hide and a smaller unit of a hide at least as full change places;
// - re-pack: that hide and a fuller one packed again by the greedy, the fuller first, in a perturbed
//   largest-first order (engine/nest/hide_repack);
// - shrink: every unit of a used hide onto an unused smaller hide, no dearer, that has room for
//   their area (the same pieces on less leather; also the only move left once the used hides are as
//   few as their area allows).
// All of them (but an emptying chain) raise the sum over hides of placed area x fill, so none undoes
// another; a hide that loses its last unit is closed (multi-hide form: fewer hides, the others fuller). Each level of
// effort (a failed cycle) lengthens the separations, adds a destination and drops the inserted piece
// at a random pose instead of the hide's centre; a success resets it. Restarts: the outcome hangs on
// a few lucky moves early on, so a trajectory that still uses more hides than the best one after a
// failed cycle (one as good as the best: after three) is dropped for a new one from the greedy in a
// perturbed order; the best of all trajectories is returned (the most placed area, then the fewest
// hides, then the least leather, then the most concentrated: HideSearchState::better_than). The search runs until the budget (or, at the area bound, where
// only shrinks and replacing chains are left, until 40 of them in a row failed; with pieces still left
// over, as on one hide in the knapsack form, such a failed run starts a new trajectory instead).
// Regrouping (engine/nest/hide_move_regroup): once the best layout has kept its number of hides for
// regroup_after_rounds rounds, and the first hides of the opening order, one fewer than it uses, could
// hold its pieces at regroup_fill by area with at most regroup_units_per_hide units a hide on average,
// the layout is regrouped onto those hides (engine/nest/hide_regroup: which units go on which hide
// searched as bin packing, each hide's packing asked of this search on that hide alone, handed to it
// as a callback), within regroup_time_share of the time left; once per number of hides. Found, it
// becomes the trajectory and the best layout.
// The moves above carry one unit at a time between packed hides and stall where the pieces are large
// next to the hides (Baldacci Test6 stayed on 11 hides whatever the seed; regrouped, 10); with many
// small units a hide (shoe batches) the moves do well and each per-hide search is long.
// Pair groups move as one unit and must end near each other (engine/nest/hide_pieces).
// Deterministic for the seed, sweep workers and iteration budget (the regrouping's per-hide searches
// then run on rounds too); the time limit only stops it (a round cut short is dropped). No threads of
// its own: sweeps go through NestOptions::run_parallel.
#include "engine/nest/hide_pieces.hpp"
#include "engine/nest/layout.hpp"
#include "engine/nest/nest_options.hpp"

namespace lastcut::nest_detail {

Layout nest_hides_search(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options);

// The same search's best placement, without making it a layout (the regrouping's per-hide oracle).
HidePlacement search_hide_placement(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options);

}  // namespace lastcut::nest_detail
