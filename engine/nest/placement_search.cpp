#include "engine/nest/placement_search.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace lastcut::nest_detail {
namespace {

constexpr double kNoBound = std::numeric_limits<double>::infinity();
// Step schedule of the two descents, as ratios of the piece's smaller box side (sparrow's values).
constexpr double kCoarseFirst = 0.25, kCoarseLast = 0.02, kFineFirst = 0.01, kFineLast = 0.001;
constexpr double kStepSuccess = 1.1, kStepFailure = 0.5;
// Two samples closer than this share of the smaller box side (and in the same pose) count as one.
constexpr double kDistinctShare = 0.05;

struct Sample {
  PieceState state;
  double cost = kNoBound;
};

// The best `capacity` samples, pairwise distinct, cheapest first.
class BestSamples {
 public:
  BestSamples(size_t capacity, double distinct_mm) : capacity_(capacity), distinct_mm_(distinct_mm) {}
  double bound() const { return samples_.size() < capacity_ ? kNoBound : samples_.back().cost; }
  const std::vector<Sample>& samples() const { return samples_; }
  void report(const Sample& s) {
    for (Sample& known : samples_)
      if (known.state.orientation == s.state.orientation &&
          (known.state.offset - s.state.offset).squaredNorm() < distinct_mm_ * distinct_mm_) {
        if (s.cost < known.cost) known = s, sort();
        return;
      }
    if (samples_.size() == capacity_ && s.cost >= samples_.back().cost) return;
    samples_.push_back(s);
    sort();
    if (samples_.size() > capacity_) samples_.pop_back();
  }

 private:
  void sort() {
    std::stable_sort(samples_.begin(), samples_.end(), [](const Sample& a, const Sample& b) { return a.cost < b.cost; });
  }
  size_t capacity_;
  double distinct_mm_;
  std::vector<Sample> samples_;
};

double smaller_side(const PreparedItem& item, const PieceState& state) {
  const Box& box = item.orientations[state.orientation].box;
  return std::min(box.width(), box.height());
}

Sample descend(Sample start, double first_step, double last_step, const Container& container,
               const OrientedShape& shape, const PlacementCost& cost, Random& random) {
  static constexpr double kAxes[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
  double step_x = first_step, step_y = first_step;
  int axis = random.below(4);
  while ((step_x >= last_step || step_y >= last_step) && start.cost > 0) {
    const Point2 step(kAxes[axis][0] * step_x, kAxes[axis][1] * step_y);
    Sample best;
    for (const double sign : {1.0, -1.0}) {
      Sample candidate{start.state, kNoBound};
      candidate.state.offset = container.clamp_offset(shape, start.state.offset + sign * step);
      candidate.cost = cost(candidate.state, start.cost);
      if (candidate.cost < best.cost) best = candidate;
    }
    const bool better = best.cost < start.cost;
    if (best.cost <= start.cost) start = best;
    const double factor = better ? kStepSuccess : kStepFailure;
    if (axis == 0) step_x *= factor;
    else if (axis == 1) step_y *= factor;
    else step_x *= std::sqrt(factor), step_y *= std::sqrt(factor);
    if (!better) axis = random.below(4);
  }
  return start;
}

}  // namespace

std::pair<PieceState, double> search_placement(const PreparedItem& item, const PieceState& current,
                                               const Container& container, const PlacementCost& cost,
                                               const SearchSettings& settings, Random& random) {
  const int orientations = static_cast<int>(item.orientations.size());
  BestSamples best(static_cast<size_t>(settings.refined_samples), kDistinctShare * smaller_side(item, current));
  best.report({current, cost(current, kNoBound)});
  const double radius = 0.25 * item.diameter_mm;
  for (int k = 0; k < settings.focused_samples && best.samples().front().cost > 0; ++k) {
    Sample s{{random.uniform() < 0.7 ? current.orientation : random.below(orientations), current.offset}, kNoBound};
    const Box range = container.offset_range(item.orientations[s.state.orientation]);
    if (range.x0 > range.x1 || range.y0 > range.y1) continue;
    s.state.offset = container.clamp_offset(item.orientations[s.state.orientation],
                                            s.state.offset + Point2(random.uniform(-radius, radius), random.uniform(-radius, radius)));
    s.cost = cost(s.state, best.bound());
    best.report(s);
  }
  for (int k = 0; k < settings.container_samples && best.samples().front().cost > 0; ++k) {
    Sample s{{random.below(orientations), Point2::Zero()}, kNoBound};
    const Box range = container.offset_range(item.orientations[s.state.orientation]);
    if (range.x0 > range.x1 || range.y0 > range.y1) continue;
    s.state.offset = {random.uniform(range.x0, range.x1), random.uniform(range.y0, range.y1)};
    s.cost = cost(s.state, best.bound());
    best.report(s);
  }
  const std::vector<Sample> starts = best.samples();
  for (const Sample& start : starts) {
    const double side = smaller_side(item, start.state);
    best.report(descend(start, kCoarseFirst * side, kCoarseLast * side, container,
                        item.orientations[start.state.orientation], cost, random));
  }
  const Sample& chosen = best.samples().front();
  const double side = smaller_side(item, chosen.state);
  const Sample final_sample = descend(chosen, kFineFirst * side, kFineLast * side, container,
                                      item.orientations[chosen.state.orientation], cost, random);
  return {final_sample.state, final_sample.cost};
}

}  // namespace lastcut::nest_detail
