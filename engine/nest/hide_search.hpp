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
// area first). Then rounds, each one move that is kept only when it ends feasible:
// - insert: a unit left over (highest value first) goes onto one of the two hides with the most free
//   area (the first unopened hide after the used ones): at a free sampled spot if there is one,
//   otherwise dropped in and the hide separated. A unit that fails is not tried again until a hide
//   has been closed (knapsack form).
// - move: one unit of a little-filled hide (the least filled first, the smaller hide on a tie; after
//   4 failed attempts the next hide) goes, by the same insertion, onto a hide at least as full;
// - swap (once a whole cycle over the hides failed): one unit of a little-filled hide and a smaller
//   unit of a hide at least as full change places.
//   Both raise the sum over hides of placed area x fill, so no sequence of them cycles; a hide that
//   loses its last unit is closed (multi-hide form: fewer hides, the others fuller). Every full cycle
//   over the used hides without success raises the effort (up to 3 levels: longer separations, one
//   more destination, the dropped piece at a random pose instead of the hide's centre); a success
//   resets it. With several threads each round runs one attempt per thread (each separating with one
//   sweep worker) and keeps the first that succeeds. The search runs until the budget, or until the
//   used hides are as few as their usable area allows.
// Pair groups move as one unit and must end near each other (engine/nest/hide_pieces).
// Deterministic for the seed, threads, sweep workers and iteration budget; the time limit only stops it (a
// round cut short is dropped). No threads of its own: sweeps go through NestOptions::run_parallel.
#include "engine/nest/hide_pieces.hpp"
#include "engine/nest/layout.hpp"
#include "engine/nest/nest_options.hpp"

namespace lastcut::nest_detail {

Layout nest_hides_search(const NestInstance& instance, const HidePieces& pieces, const NestOptions& options);

}  // namespace lastcut::nest_detail
