#pragma once
// What piece_yield_bench prints about one hide layout of pair groups: pieces placed, hides used, the
// utilisation of the used hides' usable area (together and the least filled hide), the rules as
// measured on the placements (grain against the backbone, pairs on one hide) and the independent
// checker's verdict (engine/nest/layout_check: also the quality zones, gaps and margins); and the
// area bound of the instance.
#include <map>
#include <string>
#include <vector>

#include "engine/nest/hide_batch.hpp"
#include "engine/nest/hide_mirror_pairs.hpp"
#include "engine/nest/layout.hpp"

namespace lastcut::bench {

struct HideFill {
  std::string hide;       // Bin::name
  double usable_mm2 = 0;  // outline minus holes
  double placed_mm2 = 0;  // the pieces on it
};

struct YieldFigures {
  int placed = 0, demanded = 0;  // pieces
  std::vector<HideFill> hides;   // the used ones, least filled first
  double utilisation = 0;        // placed area / usable area of the used hides, 0..1
  double least_hide_utilisation = 0;  // of the least filled used hide, 0..1
  // Per grain tolerance (deg): the largest deviation of a placed piece's grain from its hide's
  // backbone, either direction (deg).
  std::map<double, double> worst_grain_deg;
  int pairs = 0, pairs_on_one_hide = 0;  // pair groups, and those with every piece on one hide
  MirroredPairs twins;                    // a piece and its other foot's copy on one hide; mirrored about the backbone
  std::vector<std::string> problems;      // check_layout; empty = valid
};

YieldFigures measure_yield(const BatchInstance& batch, const Layout& layout);

struct AreaBound {
  double pieces_mm2 = 0;       // every demanded piece
  int fewest_hides = 0;        // the fewest hides (largest usable area first) whose area covers the pieces
  double best_utilisation = 0; // pieces / the smallest usable area of any set of hides covering them
};

// Over every subset of the hides (at most 24: 2^24 sums). Throws EngineError with more hides.
AreaBound area_bound(const NestInstance& instance);

}  // namespace lastcut::bench
