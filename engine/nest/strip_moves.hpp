#pragma once
// The two moves of the strip search that act on a whole layout (sparrow: Gardeyn, Vanden Berghe &
// Wauters, "An open-source heuristic to reboot 2D nesting research", arXiv:2509.13329, 2025):
// shrinking the strip by cutting a vertical slice out of it, and disrupting a layout that could not
// be separated by swapping two large pieces (and the small pieces that sat under the larger one).
// Both leave overlaps behind on purpose: the separator removes them.
#include <vector>

#include "engine/nest/nest_random.hpp"
#include "engine/nest/separator.hpp"

namespace lastcut::nest_detail {

// Moves every piece whose box centre lies right of split_x by delta_mm to the left (the strip loses
// a slice of width delta_mm at split_x), then pulls every piece back inside `range_of` its pose.
// pieces: one per copy; state: #pieces, changed in place.
void shrink_strip(const std::vector<const PreparedItem*>& pieces, std::vector<PieceState>& state, double split_x,
                  double delta_mm, const Container& container);

// Swaps two large pieces (pieces that make up the largest 75 % of the total area; the second one of a
// different size when there is one) by their box centres; pieces whose main pole lies under a swapped
// piece's new outline follow into the place it left. Pieces stay within the container's offset range.
void disrupt_layout(const std::vector<const PreparedItem*>& pieces, std::vector<PieceState>& state,
                    const Container& container, Random& random);

}  // namespace lastcut::nest_detail
