#pragma once
// Where one piece should go during separation: sparrow's sampling search (Gardeyn, Vanden Berghe &
// Wauters, arXiv:2509.13329, 2025, Algorithm 6 and Figure 7). The current spot, samples around it and
// samples over the whole container are evaluated; the best few distinct ones are refined by a coordinate
// descent (random axis among x, y and the two diagonals; a step grows by 1.1 after a success and halves
// after a failure; moves that do not make things worse are taken, so a piece can slide along a plateau),
// and the best of those once more with finer steps.
#include <functional>

#include "engine/nest/nest_random.hpp"
#include "engine/nest/separator.hpp"

namespace lastcut::nest_detail {

struct SearchSettings {
  int container_samples = 50;  // uniform over the container
  int focused_samples = 25;    // uniform within a quarter diameter of the current spot
  int refined_samples = 3;     // how many of the best distinct samples the coarse descent refines
};

// Cost of the piece in a state; may stop early and return any value above `bound` once it exceeds it.
using PlacementCost = std::function<double(const PieceState& state, double bound)>;

// The best state found for `item` starting from `current` (which it never does worse than), and its cost.
// Units: mm (offsets), the cost's own (mm for the separator's loss).
std::pair<PieceState, double> search_placement(const PreparedItem& item, const PieceState& current,
                                               const Container& container, const PlacementCost& cost,
                                               const SearchSettings& settings, Random& random);

}  // namespace lastcut::nest_detail
