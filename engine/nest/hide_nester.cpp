#include "engine/nest/hide_nester.hpp"

#include <algorithm>
#include <memory>
#include <numeric>

#include "engine/nest/hide_container.hpp"
#include "engine/nest/nest_random.hpp"
#include "engine/nest/separator.hpp"

namespace lastcut {
namespace {

using namespace nest_detail;

constexpr int kSamplesPerOrientation = 12;
constexpr int kMinSamples = 120;

struct Slot {  // one copy of one bin
  int bin_index = 0;
  int copy = 0;
  std::unique_ptr<HideContainer> container;
};

struct Attempt {
  std::vector<int> slot_of;  // per piece; -1 = not placed
  std::vector<PieceState> state;
  double placed_area = 0;
  int slots_used = 0;
  double spread = 0;  // sum of the pieces' right edges relative to their hide: smaller = more compact
  bool better_than(const Attempt& o) const {
    if (std::abs(placed_area - o.placed_area) > 1e-9 * std::max(1.0, placed_area)) return placed_area > o.placed_area;
    if (slots_used != o.slots_used) return slots_used < o.slots_used;
    return spread < o.spread;
  }
};

int samples_for(const PreparedItem& item) {
  return std::max(kMinSamples, kSamplesPerOrientation * static_cast<int>(item.orientations.size()));
}

Attempt greedy(const std::vector<const PreparedItem*>& pieces, const std::vector<Slot>& slots, const std::vector<int>& order,
               std::uint64_t seed) {
  const int n = static_cast<int>(pieces.size());
  Attempt attempt;
  attempt.slot_of.assign(n, -1);
  attempt.state.resize(n);
  int left = n;
  for (size_t s = 0; s < slots.size() && left > 0; ++s) {
    Separator separator(pieces, *slots[s].container, stream_seed(seed, s, 7));
    std::vector<char> active(n, 0);
    int placed_here = 0;
    const double x0 = slots[s].container->offset_range(pieces[0]->orientations[0]).x0 + pieces[0]->orientations[0].box.x0;
    for (int i : order) {
      if (attempt.slot_of[i] >= 0) continue;
      auto objective = [](const Box& b) { return b.x1 + 1e-3 * b.y0; };
      if (!separator.place_greedy(i, objective, samples_for(*pieces[i]), active)) continue;
      active[i] = 1;
      attempt.slot_of[i] = static_cast<int>(s);
      attempt.state[i] = separator.state()[i];
      attempt.placed_area += pieces[i]->area_mm2;
      attempt.spread += pieces[i]->orientations[attempt.state[i].orientation].box.x1 + attempt.state[i].offset.x() - x0;
      ++placed_here;
      --left;
    }
    if (placed_here > 0) ++attempt.slots_used;
  }
  return attempt;
}

Layout to_layout(const NestInstance& instance, const std::vector<const PreparedItem*>& pieces, const std::vector<Slot>& slots,
                 const Attempt& attempt, std::vector<Unplaced> unplaced) {
  Layout layout;
  layout.instance = instance.name;
  for (size_t i = 0; i < pieces.size(); ++i) {
    if (attempt.slot_of[i] < 0) continue;
    const Slot& slot = slots[attempt.slot_of[i]];
    const Pose& pose = pieces[i]->orientations[attempt.state[i].orientation].pose;
    layout.placements.push_back({instance.items[pieces[i]->item_index].id, instance.bins[slot.bin_index].id, slot.copy,
                                 pose.rotation_deg, pose.mirrored, attempt.state[i].offset.x(), attempt.state[i].offset.y()});
  }
  layout.unplaced = std::move(unplaced);
  update_utilisation(layout, instance);
  return layout;
}

// Why a piece stayed off the hides: it fits an empty hide (then the hides ran out) or none at all.
std::string unplaced_reason(const std::vector<const PreparedItem*>& pieces, int i, const std::vector<Slot>& slots, std::uint64_t seed) {
  std::vector<char> active(pieces.size(), 0);
  for (size_t s = 0; s < slots.size(); ++s) {
    Separator separator(pieces, *slots[s].container, stream_seed(seed, s, 11));
    if (separator.place_greedy(i, [](const Box& b) { return b.x1; }, 4 * samples_for(*pieces[i]), active))
      return "no room left on the " + std::to_string(slots.size()) + (slots.size() == 1 ? " hide" : " hides") + " available";
  }
  return "does not fit on any hide (too large, or blocked by defects, margin or quality zones)";
}

}  // namespace

Layout nest_hides(const NestInstance& instance, const NestOptions& options) {
  const Deadline deadline(options.time_limit_s);
  const double gap = options.gap_mm.value_or(instance.gap_mm);
  const double margin = options.margin_mm.value_or(instance.margin_mm);
  std::vector<PreparedItem> items;
  std::vector<Unplaced> unplaced;
  for (size_t k = 0; k < instance.items.size(); ++k) {
    items.push_back(prepare_item(instance.items[k], static_cast<int>(k), gap / 2, options.free_rotation_step_deg));
    if (items.back().orientations.empty() && instance.items[k].demand > 0)
      unplaced.push_back({instance.items[k].id, instance.items[k].demand, items.back().no_pose_reason});
  }
  std::vector<const PreparedItem*> pieces;
  for (const PreparedItem& item : items)
    if (!item.orientations.empty())
      for (int c = 0; c < instance.items[item.item_index].demand; ++c) pieces.push_back(&item);

  // Hides: cheapest per usable area first, the larger first on a tie.
  std::vector<Slot> slots;
  for (size_t b = 0; b < instance.bins.size(); ++b)
    for (int c = 0; c < instance.bins[b].stock; ++c)
      slots.push_back({static_cast<int>(b), c, std::make_unique<HideContainer>(instance.bins[b], margin - gap / 2)});
  std::stable_sort(slots.begin(), slots.end(), [&](const Slot& a, const Slot& b) {
    const double ca = instance.bins[a.bin_index].cost / std::max(1e-9, a.container->usable_area_mm2());
    const double cb = instance.bins[b.bin_index].cost / std::max(1e-9, b.container->usable_area_mm2());
    if (std::abs(ca - cb) > 1e-12 * std::max(ca, cb)) return ca < cb;
    return a.container->usable_area_mm2() > b.container->usable_area_mm2();
  });

  std::vector<int> order(pieces.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return pieces[a]->area_mm2 > pieces[b]->area_mm2; });
  Attempt best = greedy(pieces, slots, order, stream_seed(options.seed, 0, 0));
  auto finish = [&](const Attempt& attempt, bool with_reasons) {
    std::vector<Unplaced> all = unplaced;
    for (size_t i = 0; i < pieces.size(); ++i) {
      if (attempt.slot_of[i] >= 0) continue;
      const int id = instance.items[pieces[i]->item_index].id;
      const std::string reason = with_reasons ? unplaced_reason(pieces, static_cast<int>(i), slots, options.seed)
                                              : "no room found yet";
      auto same = std::find_if(all.begin(), all.end(), [&](const Unplaced& u) { return u.item == id && u.reason == reason; });
      if (same != all.end()) ++same->count;
      else all.push_back({id, 1, reason});
    }
    return to_layout(instance, pieces, slots, attempt, std::move(all));
  };
  if (options.on_improvement) options.on_improvement(finish(best, false));

  const int threads = std::max(1, options.threads);
  std::vector<Attempt> results(threads);
  for (long round = 1; !pieces.empty() && (!options.iteration_limit || round <= *options.iteration_limit); ++round) {
    if (deadline.passed()) break;
    std::vector<std::function<void()>> tasks;
    for (int w = 0; w < threads; ++w) {
      tasks.push_back([&, w, round] {
        Random random(stream_seed(options.seed, round, w));
        std::vector<double> key(pieces.size());
        for (size_t i = 0; i < pieces.size(); ++i) key[i] = pieces[i]->area_mm2 * (1 + 0.6 * random.uniform());
        std::vector<int> perturbed = order;
        std::stable_sort(perturbed.begin(), perturbed.end(), [&](int a, int b) { return key[a] > key[b]; });
        results[w] = greedy(pieces, slots, perturbed, random.next());
      });
    }
    if (options.run_parallel) {
      options.run_parallel(tasks);
    } else {
      for (auto& task : tasks) task();
    }
    if (deadline.passed()) break;  // a round cut short is not deterministic: drop it
    int winner = -1;
    for (int w = 0; w < threads; ++w)
      if (results[w].better_than(winner < 0 ? best : results[winner])) winner = w;
    if (winner >= 0) {
      best = results[winner];
      if (options.on_improvement) options.on_improvement(finish(best, false));
    }
  }
  return finish(best, true);
}

}  // namespace lastcut
