#include "engine/nest/strip_nester.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "engine/nest/nest_random.hpp"
#include "engine/nest/parallel_separation.hpp"
#include "engine/nest/separator.hpp"
#include "engine/nest/strip_container.hpp"
#include "engine/nest/strip_moves.hpp"

namespace lastcut {
namespace {

using namespace nest_detail;

constexpr int kConstructSamples = 400;
// The search of sparrow (Gardeyn, Vanden Berghe & Wauters, arXiv:2509.13329, 2025; Algorithms 12, 13)
// with its parameters scaled to a one-minute budget on two cores: the exploration shrinks the strip
// after every success and otherwise keeps trying at that length from a pool of failed layouts,
// disrupted; the compression (the last 20 %) shrinks the best layout by ever smaller ratios.
constexpr double kExplorationShare = 0.8;
// The exploration's shrink ratio adapts (sparrow uses a fixed 0.1 % over 20 minutes): it grows while
// every shrink separates at the first attempt and halves (down to the least) when one fails.
constexpr double kShrinkFirst = 0.01, kShrinkLeast = 0.001, kShrinkMost = 0.05;
constexpr double kShrinkGrowth = 1.25, kShrinkCut = 0.5;
// Two strikes while exploring (sparrow: 3): a failed separation costs a hundred successful ones, so
// a cheaper failure buys more attempts; at an equal budget of separation steps the nine instances'
// gaps summed 3.3 points lower over 16 runs (shapes0 and jakobs2 gained, blaz1 lost;
// docs/benchmarks-nest.md, ninth session).
constexpr int kExplorationStrikes = 2, kExplorationStale = 100;
constexpr int kCompressionStrikes = 5, kCompressionStale = 50;
constexpr double kCompressionShrinkFirst = 0.0005, kCompressionShrinkLast = 0.00001;
constexpr size_t kPoolSize = 16;
constexpr double kPoolSpread = 0.25;

std::string format_mm(double mm) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", mm);
  return text;
}

struct Pieces {
  std::vector<PreparedItem> items;                  // one per NestItem
  std::vector<const PreparedItem*> pieces;          // one per copy to place
  std::vector<Unplaced> unplaced;
};

Pieces prepare(const NestInstance& instance, double grow_mm, double inset_mm, const NestOptions& options) {
  Pieces result;
  const double usable_height = *instance.strip_height - 2 * inset_mm;
  result.items.reserve(instance.items.size());
  for (size_t k = 0; k < instance.items.size(); ++k) {
    const NestItem& item = instance.items[k];
    PreparedItem prepared = prepare_item(item, static_cast<int>(k), grow_mm, options.free_rotation_step_deg);
    // Keep only the poses that fit the strip's height.
    std::erase_if(prepared.orientations, [&](const OrientedShape& s) { return s.box.height() > usable_height; });
    if (item.demand > 0 && prepared.orientations.empty()) {
      const std::string reason = !prepared.no_pose_reason.empty()
                                     ? prepared.no_pose_reason
                                     : "taller than the usable strip height (" + format_mm(usable_height) + " mm) in every allowed rotation";
      result.unplaced.push_back({item.id, item.demand, reason});
    }
    result.items.push_back(std::move(prepared));
  }
  for (const PreparedItem& prepared : result.items)
    if (!prepared.orientations.empty())
      for (int c = 0; c < instance.items[prepared.item_index].demand; ++c) result.pieces.push_back(&prepared);
  return result;
}

double strip_length(const std::vector<const PreparedItem*>& pieces, const std::vector<PieceState>& state, double inset) {
  double right = 0;
  for (size_t i = 0; i < pieces.size(); ++i)
    right = std::max(right, pieces[i]->orientations[state[i].orientation].box.x1 + state[i].offset.x());
  return right + inset;
}

Layout to_layout(const NestInstance& instance, const Pieces& pieces, const std::vector<PieceState>& state, double length) {
  Layout layout;
  layout.instance = instance.name;
  layout.strip_length = length;
  for (size_t i = 0; i < pieces.pieces.size(); ++i) {
    const PreparedItem& p = *pieces.pieces[i];
    const Pose& pose = p.orientations[state[i].orientation].pose;
    layout.placements.push_back({instance.items[p.item_index].id, -1, 0, pose.rotation_deg, pose.mirrored,
                                 state[i].offset.x(), state[i].offset.y()});
  }
  layout.unplaced = pieces.unplaced;
  update_utilisation(layout, instance);
  return layout;
}

// Greedy start: biggest pieces first, each at the sampled feasible spot with the smallest right edge.
std::vector<PieceState> construct(const Pieces& pieces, double height, double inset, std::uint64_t seed) {
  double total_width = 0;
  for (const PreparedItem* p : pieces.pieces) total_width += p->orientations[0].box.width() + p->diameter_mm;
  StripContainer container(total_width + 2 * std::abs(inset) + 1, height, inset);
  Separator separator(pieces.pieces, container, seed);
  const int n = static_cast<int>(pieces.pieces.size());
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return pieces.pieces[a]->area_mm2 > pieces.pieces[b]->area_mm2; });
  std::vector<char> active(n, 0);
  const double tie = 1e-3;
  double right = inset;
  for (int i : order) {
    auto objective = [tie](const Box& b) { return b.x1 + tie * b.y0; };
    if (!separator.place_greedy(i, objective, kConstructSamples, active)) {
      // Nothing sampled was free: put the piece right of everything placed so far.
      std::vector<PieceState> state = separator.state();
      const OrientedShape& s = pieces.pieces[i]->orientations[0];
      state[i] = {0, Point2(right - s.box.x0 + 1e-6 * pieces.pieces[i]->diameter_mm, inset - s.box.y0)};
      separator.set_state(state);
    }
    active[i] = 1;
    const PieceState& placed = separator.state()[i];
    right = std::max(right, pieces.pieces[i]->orientations[placed.orientation].box.x1 + placed.offset.x());
  }
  return separator.state();
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A pool index, small ones likelier: |N(0, 0.25)| (Irwin-Hall approximation, platform independent) of the size.
size_t pick_from_pool(size_t size, Random& random) {
  double normal = -2;
  for (int k = 0; k < 4; ++k) normal += random.uniform();
  const double sample = std::min(0.999, std::abs(normal * std::sqrt(3.0) * kPoolSpread));
  return static_cast<size_t>(sample * static_cast<double>(size));
}

}  // namespace

Layout nest_strip(const NestInstance& instance, const NestOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const Deadline deadline(options.time_limit_s);
  const double gap = options.gap_mm.value_or(instance.gap_mm);
  const double margin = options.margin_mm.value_or(instance.margin_mm);
  const double inset = margin - gap / 2;  // outlines are grown by gap / 2
  const double height = *instance.strip_height;
  const Pieces pieces = prepare(instance, gap / 2, inset, options);
  if (pieces.pieces.empty()) {
    Layout empty = to_layout(instance, pieces, {}, 0.0);
    if (options.on_improvement) options.on_improvement(empty);
    return empty;
  }

  std::vector<PieceState> best = construct(pieces, height, inset, stream_seed(options.seed, 0, 0));
  double best_length = strip_length(pieces.pieces, best, inset);
  Layout layout = to_layout(instance, pieces, best, best_length);
  if (options.on_improvement) options.on_improvement(layout);

  // One search: exploration, then compression; every separation step keeps the best of the workers' sweeps.
  StripContainer container(best_length, height, inset);
  ParallelSeparation separation(pieces.pieces, container, stream_seed(options.seed, 1, 0), options.sweep_workers,
                                options.threads, options.run_parallel);
  Random random(stream_seed(options.seed, 2, 0));
  double shrink = kShrinkFirst;  // exploration shrink ratio
  double width = best_length;    // of the strip the next round separates on
  std::vector<PieceState> current;
  std::vector<std::pair<double, std::vector<PieceState>>> pool;  // infeasible layouts at `width`, least overlap first
  // Starts from the best layout, shrunk by `ratio` at `split_x` (the middle when negative).
  auto restart = [&](double ratio, double split_x) {
    width = best_length * (1 - ratio);
    container.set_length(width);
    current = best;
    shrink_strip(pieces.pieces, current, split_x < 0 ? 0.5 * best_length : split_x, best_length - width, container);
    pool.clear();
  };
  restart(shrink, -1);

  // How far the search is through its budget (0..1): separation steps, rounds or time, whichever bounds it.
  const long rounds = options.iteration_limit.value_or(0);
  auto progress = [&](long rounds_done) {
    if (options.sweep_limit) return static_cast<double>(separation.steps()) / static_cast<double>(*options.sweep_limit);
    if (options.iteration_limit) return static_cast<double>(rounds_done) / static_cast<double>(rounds);
    return seconds_since(start) / options.time_limit_s;
  };
  for (long round = 0; !options.iteration_limit || round < rounds; ++round) {
    if (deadline.passed() || (options.sweep_limit && separation.steps() >= *options.sweep_limit)) break;
    const bool compressing = progress(round) >= kExplorationShare;
    const long step_limit = options.sweep_limit.value_or(ParallelSeparation::kNoStepLimit);
    container.set_length(width);
    separation.set_state(current);
    const bool success = compressing ? separation.separate(kCompressionStrikes, kCompressionStale, deadline, step_limit)
                                     : separation.separate(kExplorationStrikes, kExplorationStale, deadline, step_limit);
    // A round cut short by the time or step budget is dropped (it would not be deterministic).
    if (deadline.passed() || (!success && separation.steps() >= step_limit)) break;
    if (success) {
      const double length = strip_length(pieces.pieces, separation.state(), inset);
      if (length < best_length) {
        best = separation.state();
        best_length = length;
        layout = to_layout(instance, pieces, best, best_length);
        if (options.on_improvement) options.on_improvement(layout);
      }
    }
    if (compressing) {
      const double phase = (progress(round + 1) - kExplorationShare) / (1 - kExplorationShare);
      restart(kCompressionShrinkFirst + std::clamp(phase, 0.0, 1.0) * (kCompressionShrinkLast - kCompressionShrinkFirst),
              random.uniform(0, best_length));
    } else if (success) {
      if (pool.empty()) shrink = std::min(kShrinkMost, shrink * kShrinkGrowth);
      // Cut at a random place, as the compression does (sparrow cuts at the middle while exploring): on
      // jakobs2 the middle of the strip crosses pieces whose widths add up to the strip, so a middle
      // cut always leaves overlaps there, while some other cut finds a gap (docs/benchmarks-nest.md).
      restart(shrink, random.uniform(0, best_length));
    } else if (shrink > kShrinkLeast) {
      // Too bold a shrink: retry the least overlapping layout on a strip half as much shorter than the best.
      shrink = std::max(kShrinkLeast, shrink * kShrinkCut);
      width = std::max(width, best_length * (1 - shrink));
      current = separation.state();
      pool.clear();
    } else {
      // Keep the failed layout; go on from one of the least overlapping ones, disrupted.
      const double loss = separation.total_overlap();
      auto at = std::lower_bound(pool.begin(), pool.end(), loss, [](const auto& e, double l) { return e.first < l; });
      pool.insert(at, {loss, separation.state()});
      if (pool.size() > kPoolSize) pool.pop_back();
      current = pool[pick_from_pool(pool.size(), random)].second;
      disrupt_layout(pieces.pieces, current, container, random);
    }
  }
  return layout;
}

}  // namespace lastcut
