#include "engine/nest/separator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/nest/overlap_proxy.hpp"

namespace lastcut::nest_detail {
namespace {

constexpr int kGlobalSamples = 50;
constexpr int kLocalSamples = 25;
constexpr int kRefineEvaluations = 60;
constexpr double kWeightGrowthLow = 1.2, kWeightGrowthHigh = 2.0, kWeightDecay = 0.95;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

PlacedRing placed(const OrientedShape& shape, const Point2& offset) {
  return {&shape.outline, shape.box, offset, shape.poles.empty() ? nullptr : &shape.poles.front().center};
}

}  // namespace

Separator::Separator(std::vector<const PreparedItem*> pieces, const Container& container, std::uint64_t seed)
    : pieces_(std::move(pieces)), container_(container), random_(seed), n_(static_cast<int>(pieces_.size())) {
  state_.resize(n_);
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
  const Box world = s.box.shifted(candidate.offset);
  for (int j = 0; j < n_; ++j) {
    if (j == i || (active && !(*active)[j])) continue;
    const OrientedShape& t = pieces_[j]->orientations[state_[j].orientation];
    if (!world.overlaps(t.box.shifted(state_[j].offset))) continue;
    if (!rings_collide(placed(s, candidate.offset), placed(t, state_[j].offset))) continue;
    const double w = weight_[static_cast<size_t>(i) * n_ + j] * scale_[i] * scale_[j];
    const double room = (bound - cost) / w;
    cost += w * std::sqrt(pair_overlap(s, candidate.offset, t, state_[j].offset, eps(i, j),
                                       room < kInfinity ? room * room : kInfinity));
    if (cost > bound) return cost;
  }
  return cost;
}

bool Separator::collides_any(int i, const PieceState& candidate, const std::vector<char>& active) const {
  const OrientedShape& s = pieces_[i]->orientations[candidate.orientation];
  if (container_.exterior_overlap(s, candidate.offset, pieces_[i]->min_quality, eps(i, i)) > 0) return true;
  const Box world = s.box.shifted(candidate.offset);
  for (int j = 0; j < n_; ++j) {
    if (j == i || !active[j]) continue;
    const OrientedShape& t = pieces_[j]->orientations[state_[j].orientation];
    if (world.overlaps(t.box.shifted(state_[j].offset)) &&
        rings_collide(placed(s, candidate.offset), placed(t, state_[j].offset)))
      return true;
  }
  return false;
}

void Separator::update_overlaps(int i) {
  const OrientedShape& s = pieces_[i]->orientations[state_[i].orientation];
  exterior_[i] = scale_[i] * scale_[i] * std::sqrt(container_.exterior_overlap(s, state_[i].offset, pieces_[i]->min_quality, eps(i, i)));
  const Box world = s.box.shifted(state_[i].offset);
  for (int j = 0; j < n_; ++j) {
    if (j == i) continue;
    const OrientedShape& t = pieces_[j]->orientations[state_[j].orientation];
    double o = 0;
    if (world.overlaps(t.box.shifted(state_[j].offset)) &&
        rings_collide(placed(s, state_[i].offset), placed(t, state_[j].offset)))
      o = scale_[i] * scale_[j] * std::sqrt(pair_overlap(s, state_[i].offset, t, state_[j].offset, eps(i, j)));
    overlap_[static_cast<size_t>(i) * n_ + j] = overlap_[static_cast<size_t>(j) * n_ + i] = o;
  }
}

void Separator::recompute_all() {
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

PieceState Separator::refine(int i, PieceState start, double& cost) {
  const double diameter = pieces_[i]->diameter_mm;
  double step = 0.05 * diameter;
  const double min_step = 1e-4 * diameter;
  static constexpr double directions[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (int evaluations = 0; step > min_step && evaluations < kRefineEvaluations;) {
    bool improved = false;
    for (const auto& d : directions) {
      PieceState candidate = start;
      candidate.offset += Point2(d[0], d[1]) * step;
      const double c = weighted_cost(i, candidate, cost, nullptr);
      ++evaluations;
      if (c < cost) {
        start = candidate, cost = c, improved = true;
        break;
      }
    }
    step *= improved ? 1.5 : 0.5;
    if (cost == 0) break;
  }
  return start;
}

void Separator::move_piece(int i) {
  const PreparedItem& item = *pieces_[i];
  const int orientations = static_cast<int>(item.orientations.size());
  const PieceState current = state_[i];
  double current_cost = weighted_cost(i, current, kInfinity, nullptr);
  PieceState best_global = current, best_local = current;
  double global_cost = kInfinity, local_cost = kInfinity;
  for (int k = 0; k < kGlobalSamples && global_cost > 0; ++k) {
    PieceState candidate{random_.below(orientations), Point2::Zero()};
    const Box range = container_.offset_range(item.orientations[candidate.orientation]);
    if (range.x0 > range.x1 || range.y0 > range.y1) continue;
    candidate.offset = {random_.uniform(range.x0, range.x1), random_.uniform(range.y0, range.y1)};
    const double c = weighted_cost(i, candidate, global_cost, nullptr);
    if (c < global_cost) global_cost = c, best_global = candidate;
  }
  const double radius = 0.25 * item.diameter_mm;
  for (int k = 0; k < kLocalSamples && local_cost > 0 && global_cost > 0; ++k) {
    PieceState candidate{random_.uniform() < 0.7 ? current.orientation : random_.below(orientations), current.offset};
    const Box range = container_.offset_range(item.orientations[candidate.orientation]);
    if (range.x0 > range.x1 || range.y0 > range.y1) continue;
    candidate.offset += Point2(random_.uniform(-radius, radius), random_.uniform(-radius, radius));
    candidate.offset = {std::clamp(candidate.offset.x(), range.x0, range.x1), std::clamp(candidate.offset.y(), range.y0, range.y1)};
    const double c = weighted_cost(i, candidate, local_cost, nullptr);
    if (c < local_cost) local_cost = c, best_local = candidate;
  }
  PieceState best = current;
  double best_cost = current_cost;
  if (global_cost < kInfinity) {
    best_global = refine(i, best_global, global_cost);
    if (global_cost < best_cost) best = best_global, best_cost = global_cost;
  }
  if (local_cost < kInfinity && best_cost > 0) {
    best_local = refine(i, best_local, local_cost);
    if (local_cost < best_cost) best = best_local, best_cost = local_cost;
  }
  if (best_cost > 0 && best_cost == current_cost) {
    best = refine(i, current, current_cost);
  }
  state_[i] = best;
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

bool Separator::separate(int max_strikes, int max_stale_iterations, const Deadline& deadline) {
  std::fill(weight_.begin(), weight_.end(), 1.0);
  std::fill(exterior_weight_.begin(), exterior_weight_.end(), 1.0);
  recompute_all();
  double best_total = total_overlap();
  if (best_total == 0) return true;
  std::vector<PieceState> best_state = state_;
  std::vector<int> order;
  // A strike is a run of sweeps that ends without a substantial (2 %) improvement on the overlap it
  // started from; a substantial improvement also resets the stale counter (sparrow, Algorithm 9).
  constexpr double kSubstantial = 0.98;
  for (int strike = 0; strike < max_strikes;) {
    const double strike_start = total_overlap();
    for (int stale = 0; stale < max_stale_iterations;) {
      if (deadline.passed()) {
        set_state(best_state);
        return false;
      }
      order.clear();
      for (int i = 0; i < n_; ++i) order.push_back(i);
      for (int k = n_ - 1; k > 0; --k) std::swap(order[k], order[random_.below(k + 1)]);
      for (int i : order) {
        double row = exterior_[i];
        for (int j = 0; j < n_; ++j) row += overlap_[static_cast<size_t>(i) * n_ + j];
        if (row > 0) move_piece(i);
      }
      const double total = total_overlap();
      if (total == 0) return true;
      if (total < best_total) {
        if (total < kSubstantial * best_total) stale = 0;
        best_total = total, best_state = state_;
      } else {
        ++stale;
      }
      update_weights();
    }
    strike = best_total < kSubstantial * strike_start ? 0 : strike + 1;
    set_state(best_state);  // back to the least overlap, keeping the weights learnt so far
  }
  return false;
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
