#pragma once
// The moves of overlap minimisation by guided local search: pieces may overlap temporarily; every
// overlapping piece in turn moves to the position (sampled globally and around itself, then refined
// by coordinate descent) that minimises its weighted overlap; the weights of pairs that keep
// overlapping grow, so the search leaves local minima. The loop that runs sweeps until no overlap
// is left is engine/nest/parallel_separation.
// A pair's loss is sqrt(pole overlap proxy) x (area_i x area_j)^(1/4), the container's likewise with
// the piece's own area (sparrow's Algorithm 4: linear in penetration depth, scaled by size), so a few
// deep overlaps do not drown many shallow ones.
// Method: sparrow (Gardeyn, Vanden Berghe & Wauters, arXiv:2509.13329, 2025); GLS for nesting:
// Egeblad, Nielsen & Odgaard 2007; separation by overlap minimisation: Imamichi, Yagiura &
// Nagamochi 2009; penetration-depth based overlap: Umetani et al. 2009.
#include <algorithm>
#include <functional>
#include <vector>

#include "engine/nest/nest_random.hpp"
#include "engine/nest/nest_shapes.hpp"

namespace lastcut::nest_detail {

// Where pieces may go. offset_range: the translations that keep the piece's bounding box inside the
// container's bounding box (x0 > x1 when it cannot fit). exterior_overlap: 0 when the piece is inside
// and clear of every hazard its min_quality forbids, positive otherwise (mm^2, like pair_overlap).
class Container {
 public:
  virtual ~Container() = default;
  virtual Box offset_range(const OrientedShape& shape) const = 0;
  virtual double exterior_overlap(const OrientedShape& shape, const Point2& offset, int min_quality,
                                  double eps_mm) const = 0;
  // The nearest offset within offset_range(shape); the range's low end on an axis where it is empty.
  Point2 clamp_offset(const OrientedShape& shape, const Point2& offset) const {
    const Box range = offset_range(shape);
    return {range.x0 <= range.x1 ? std::clamp(offset.x(), range.x0, range.x1) : range.x0,
            range.y0 <= range.y1 ? std::clamp(offset.y(), range.y0, range.y1) : range.y0};
  }
};

struct PieceState {
  int orientation = 0;  // index into PreparedItem::orientations
  Point2 offset = Point2::Zero();
};

class Separator {
 public:
  // pieces: one entry per copy to place (pointers stay valid for the separator's life).
  Separator(std::vector<const PreparedItem*> pieces, const Container& container, std::uint64_t seed);

  // Sets the pieces' poses and offsets, keeping the GLS weights learnt so far.
  void set_state(const std::vector<PieceState>& state);
  const std::vector<PieceState>& state() const { return state_; }
  // Sum of all unweighted losses (0: feasible).
  double total_overlap() const;
  // The unweighted loss of one pair (i != j) and of piece i against the container (0: clear).
  double pair_loss(int i, int j) const { return overlap_[static_cast<size_t>(i) * n_ + j]; }
  double exterior_loss(int i) const { return exterior_[i]; }
  // Sum of all losses times their GLS weights: what a sweep lowers.
  double total_weighted_overlap() const;
  // Back to weight 1 for every pair (the start of a separation).
  void reset_weights();
  // One GLS iteration's moves: every overlapping piece, in random order, moves to the best spot
  // sparrow's sampling search finds for it (engine/nest/placement_search).
  void sweep();
  // The GLS weight update after a sweep: weights of overlapping pairs grow with their overlap, the others decay.
  void update_weights();
  // Takes over another separator's state and weights (same pieces and container).
  void adopt(const Separator& other);
  // Greedy placement of pieces `order` one by one at the feasible spot minimising
  // objective(world box) among sampled and refined candidates; pieces not in `order` are ignored.
  // Returns false (piece left where it was) when no sampled spot is feasible.
  using Objective = std::function<double(const Box& world_box)>;
  bool place_greedy(int piece, const Objective& objective, int samples, const std::vector<char>& active);

 private:
  double eps(int a, int b) const;
  // Weighted overlap of piece i in the given state with the container and active others; stops above bound.
  double weighted_cost(int i, const PieceState& candidate, double bound, const std::vector<char>* active) const;
  bool collides_any(int i, const PieceState& candidate, const std::vector<char>& active) const;
  void update_overlaps(int i);
  void recompute_all();
  void move_piece(int i);

  std::vector<const PreparedItem*> pieces_;
  const Container& container_;
  Random random_;
  int n_ = 0;
  std::vector<PieceState> state_;
  std::vector<Box> world_box_;   // per piece: its outline's box where it stands (kept with state_)
  std::vector<double> overlap_;  // n x n, symmetric, unweighted pair overlap
  std::vector<double> weight_;   // n x n GLS weights (>= 1)
  std::vector<double> exterior_, exterior_weight_;
  std::vector<double> scale_;    // per piece: area^(1/4), so a pair's loss scales like sparrow's (Algorithm 4)
  // weighted_cost's scratch: the pieces whose boxes meet the candidate's, with their loss when their
  // largest poles meet (-1: not known yet). One separator is used by one thread at a time.
  struct NearPiece {
    int j;
    double loss;
  };
  mutable std::vector<NearPiece> near_;
};

}  // namespace lastcut::nest_detail
