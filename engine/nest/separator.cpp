#include "engine/nest/separator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/nest/overlap_proxy.hpp"
#include "engine/nest/placement_search.hpp"

namespace lastcut::nest_detail {
namespace {

constexpr double kWeightGrowthLow = 1.2, kWeightGrowthHigh = 2.0, kWeightDecay = 0.95;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

PlacedRing placed(const OrientedShape& shape, const Point2& offset) {
  return {&shape.outline, shape.box, offset, shape.poles.empty() ? nullptr : &shape.poles.front().center};
}

// Fail-fast collision test (after jagua-rs): the largest poles of two pieces lie inside their outlines,
// so when two of them intersect the pieces collide and the exact edge test is not needed.
bool largest_poles_meet(const OrientedShape& a, const Point2& offset_a, const OrientedShape& b, const Point2& offset_b) {
  constexpr size_t kFailFastPoles = 2;
  const Point2 shift = offset_a - offset_b;
  for (size_t k = 0; k < std::min(kFailFastPoles, a.poles.size()); ++k)
    for (size_t l = 0; l < std::min(kFailFastPoles, b.poles.size()); ++l) {
      const Pole& p = a.poles[k];
      const Pole& q = b.poles[l];
      // Shrunk by a rounding margin: the radii are distances to the outline, computed in doubles.
      const double reach = (p.radius_mm + q.radius_mm) * (1 - 1e-9);
      if ((p.center + shift - q.center).squaredNorm() < reach * reach) return true;
    }
  return false;
}

// Whether the two placed outlines collide: boxes, then the fail-fast poles, then the exact edge test.
bool shapes_collide(const OrientedShape& a, const Point2& offset_a, const OrientedShape& b, const Point2& offset_b) {
  return a.box.shifted(offset_a).overlaps(b.box.shifted(offset_b)) &&
         (largest_poles_meet(a, offset_a, b, offset_b) || rings_collide(placed(a, offset_a), placed(b, offset_b)));
}

}  // namespace

Separator::Separator(std::vector<const PreparedItem*> pieces, const Container& container, std::uint64_t seed)
    : pieces_(std::move(pieces)), container_(container), random_(seed), n_(static_cast<int>(pieces_.size())) {
  state_.resize(n_);
  world_box_.resize(n_);
  overlap_.assign(static_cast<size_t>(n_) * n_, 0.0);
  weight_.assign(static_cast<size_t>(n_) * n_, 1.0);
  exterior_.assign(n_, 0.0);
  exterior_weight_.assign(n_, 1.0);
  for (const PreparedItem* p : pieces_) scale_.push_back(std::sqrt(std::sqrt(std::max(p->area_mm2, 1e-12))));
}

void Separator::set_state(const std::vector<PieceState>& state) {
  state_ = state;
  recompute_all();
}

double Separator::eps(int a, int b) const {
  return 0.01 * std::min(pieces_[a]->diameter_mm, pieces_[b]->diameter_mm);
}

double Separator::weighted_cost(int i, const PieceState& candidate, double bound,
                                const std::vector<char>* active) const {
  const OrientedShape& s = pieces_[i]->orientations[candidate.orientation];
  double cost = exterior_weight_[i] * scale_[i] * scale_[i] *
                std::sqrt(container_.exterior_overlap(s, candidate.offset, pieces_[i]->min_quality, eps(i, i)));
  if (cost > bound) return cost;
  auto loss = [&](int j, double sum) {
    const OrientedShape& t = pieces_[j]->orientations[state_[j].orientation];
    const double w = weight_[static_cast<size_t>(i) * n_ + j] * scale_[i] * scale_[j];
    const double room = (bound - sum) / w;
    return w * std::sqrt(pair_overlap(s, candidate.offset, t, state_[j].offset, eps(i, j),
                                      room < kInfinity ? room * room : kInfinity));
  };
  // First the pairs whose largest poles meet (sure collisions, no edge test needed): most rejected
  // samples exceed the bound on these alone, before any exact edge test is paid for.
  const Box world = s.box.shifted(candidate.offset);
  near_.clear();
  double sure = cost;
  for (int j = 0; j < n_; ++j) {
    if (j == i || !world.overlaps(world_box_[j]) || (active && !(*active)[j])) continue;
    const OrientedShape& t = pieces_[j]->orientations[state_[j].orientation];
    const bool poles_meet = largest_poles_meet(s, candidate.offset, t, state_[j].offset);
    near_.push_back({j, poles_meet ? loss(j, sure) : -1.0});
    if (poles_meet && (sure += near_.back().loss) > bound) return sure;
  }
  // Then every colliding pair in index order, so the sum does not depend on the order of discovery.
  for (const NearPiece& near : near_) {
    if (near.loss < 0) {
      const OrientedShape& t = pieces_[near.j]->orientations[state_[near.j].orientation];
      if (!rings_collide(placed(s, candidate.offset), placed(t, state_[near.j].offset))) continue;
      cost += loss(near.j, cost);
    } else {
      cost += near.loss;
    }
    if (cost > bound) return cost;
  }
  return cost;
}

bool Separator::collides_any(int i, const PieceState& candidate, const std::vector<char>& active) const {
  const OrientedShape& s = pieces_[i]->orientations[candidate.orientation];
  if (container_.exterior_overlap(s, candidate.offset, pieces_[i]->min_quality, eps(i, i)) > 0) return true;
  for (int j = 0; j < n_; ++j) {
    if (j == i || !active[j]) continue;
    const OrientedShape& t = pieces_[j]->orientations[state_[j].orientation];
    if (shapes_collide(s, candidate.offset, t, state_[j].offset)) return true;
  }
  return false;
}

void Separator::update_overlaps(int i) {
  const OrientedShape& s = pieces_[i]->orientations[state_[i].orientation];
  world_box_[i] = s.box.shifted(state_[i].offset);
  exterior_[i] = scale_[i] * scale_[i] * std::sqrt(container_.exterior_overlap(s, state_[i].offset, pieces_[i]->min_quality, eps(i, i)));
  for (int j = 0; j < n_; ++j) {
    if (j == i) continue;
    const OrientedShape& t = pieces_[j]->orientations[state_[j].orientation];
    double o = 0;
    if (shapes_collide(s, state_[i].offset, t, state_[j].offset))
      o = scale_[i] * scale_[j] * std::sqrt(pair_overlap(s, state_[i].offset, t, state_[j].offset, eps(i, j)));
    overlap_[static_cast<size_t>(i) * n_ + j] = overlap_[static_cast<size_t>(j) * n_ + i] = o;
  }
}

void Separator::recompute_all() {
  for (int i = 0; i < n_; ++i) world_box_[i] = pieces_[i]->orientations[state_[i].orientation].box.shifted(state_[i].offset);
  for (int i = 0; i < n_; ++i) update_overlaps(i);
}

double Separator::total_overlap() const {
  double total = 0;
  for (int i = 0; i < n_; ++i) {
    total += exterior_[i];
    for (int j = i + 1; j < n_; ++j) total += overlap_[static_cast<size_t>(i) * n_ + j];
  }
  return total;
}

void Separator::move_piece(int i) {
  const auto cost = [this, i](const PieceState& candidate, double bound) { return weighted_cost(i, candidate, bound, nullptr); };
  state_[i] = search_placement(*pieces_[i], state_[i], container_, cost, SearchSettings{}, random_).first;
  update_overlaps(i);
}

void Separator::update_weights() {
  double largest = 0;
  for (double o : overlap_) largest = std::max(largest, o);
  for (double o : exterior_) largest = std::max(largest, o);
  if (largest <= 0) return;
  auto update = [largest](double& weight, double o) {
    weight = o > 0 ? weight * (kWeightGrowthLow + (kWeightGrowthHigh - kWeightGrowthLow) * o / largest)
                   : std::max(1.0, weight * kWeightDecay);
  };
  for (int i = 0; i < n_; ++i) {
    update(exterior_weight_[i], exterior_[i]);
    for (int j = i + 1; j < n_; ++j) {
      update(weight_[static_cast<size_t>(i) * n_ + j], overlap_[static_cast<size_t>(i) * n_ + j]);
      weight_[static_cast<size_t>(j) * n_ + i] = weight_[static_cast<size_t>(i) * n_ + j];
    }
  }
}

double Separator::total_weighted_overlap() const {
  double total = 0;
  for (int i = 0; i < n_; ++i) {
    total += exterior_weight_[i] * exterior_[i];
    for (int j = i + 1; j < n_; ++j) total += weight_[static_cast<size_t>(i) * n_ + j] * overlap_[static_cast<size_t>(i) * n_ + j];
  }
  return total;
}

void Separator::reset_weights() {
  std::fill(weight_.begin(), weight_.end(), 1.0);
  std::fill(exterior_weight_.begin(), exterior_weight_.end(), 1.0);
  recompute_all();
}

void Separator::sweep() {
  std::vector<int> order(n_);
  for (int i = 0; i < n_; ++i) order[i] = i;
  for (int k = n_ - 1; k > 0; --k) std::swap(order[k], order[random_.below(k + 1)]);
  for (int i : order) {
    double row = exterior_[i];
    for (int j = 0; j < n_; ++j) row += overlap_[static_cast<size_t>(i) * n_ + j];
    if (row > 0) move_piece(i);
  }
}

void Separator::adopt(const Separator& other) {
  state_ = other.state_;
  world_box_ = other.world_box_;
  overlap_ = other.overlap_;
  weight_ = other.weight_;
  exterior_ = other.exterior_;
  exterior_weight_ = other.exterior_weight_;
}

bool Separator::place_greedy(int i, const Objective& objective, int samples, const std::vector<char>& active) {
  const PreparedItem& item = *pieces_[i];
  const int orientations = static_cast<int>(item.orientations.size());
  PieceState best;
  double best_score = kInfinity;
  for (int k = 0; k < samples; ++k) {
    PieceState candidate{k % orientations, Point2::Zero()};
    const Box range = container_.offset_range(item.orientations[candidate.orientation]);
    if (range.x0 > range.x1 || range.y0 > range.y1) continue;
    candidate.offset = {random_.uniform(range.x0, range.x1), random_.uniform(range.y0, range.y1)};
    const double score = objective(item.orientations[candidate.orientation].box.shifted(candidate.offset));
    if (score >= best_score || collides_any(i, candidate, active)) continue;
    best = candidate, best_score = score;
  }
  if (best_score == kInfinity) return false;
  // Slide towards a better objective while staying feasible, halving the step when stuck.
  static constexpr double directions[4][2] = {{-1, 0}, {0, -1}, {0, 1}, {1, 0}};
  for (double step = 0.25 * item.diameter_mm; step > 1e-4 * item.diameter_mm;) {
    bool moved = false;
    for (const auto& d : directions) {
      PieceState candidate = best;
      candidate.offset += Point2(d[0], d[1]) * step;
      const double score = objective(item.orientations[candidate.orientation].box.shifted(candidate.offset));
      if (score < best_score && !collides_any(i, candidate, active)) {
        best = candidate, best_score = score, moved = true;
        break;
      }
    }
    if (!moved) step *= 0.5;
  }
  state_[i] = best;
  update_overlaps(i);
  return true;
}

}  // namespace lastcut::nest_detail
