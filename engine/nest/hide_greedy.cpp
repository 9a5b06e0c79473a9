#include "engine/nest/hide_greedy.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "engine/nest/nest_random.hpp"

namespace lastcut::nest_detail {
namespace {

constexpr int kSamplesPerOrientation = 12;
constexpr int kMinSamples = 120;
// Largest factor of a unit's area in a perturbed order, minus one: enough that units up to 1.6 times
// apart in area change places, so a restart reaches other layouts; the largest still tend to go first.
constexpr double kOrderNoise = 0.6;

int samples_for(const PreparedItem& item) {
  return std::max(kMinSamples, kSamplesPerOrientation * static_cast<int>(item.orientations.size()));
}

}  // namespace

bool HideAssignment::better_than(const HideAssignment& o) const {
  if (std::abs(placed_area - o.placed_area) > 1e-9 * std::max(1.0, placed_area)) return placed_area > o.placed_area;
  if (slots_used != o.slots_used) return slots_used < o.slots_used;
  return spread < o.spread;
}

std::vector<int> unit_order_by_value(const HidePieces& pieces) {
  std::vector<int> order(pieces.units.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    if (pieces.unit_priority[a] != pieces.unit_priority[b]) return pieces.unit_priority[a] > pieces.unit_priority[b];
    return pieces.unit_area_mm2[a] > pieces.unit_area_mm2[b];
  });
  return order;
}

std::vector<int> perturbed_order(const HidePieces& pieces, std::vector<int> units, Random& random, bool priorities_first) {
  std::vector<double> key(pieces.units.size(), 0);
  for (int u : units) key[u] = pieces.unit_area_mm2[u] * (1 + kOrderNoise * random.uniform());
  std::stable_sort(units.begin(), units.end(), [&](int a, int b) {
    if (priorities_first && pieces.unit_priority[a] != pieces.unit_priority[b]) return pieces.unit_priority[a] > pieces.unit_priority[b];
    return key[a] > key[b];
  });
  return units;
}

HideAssignment greedy_hides(const NestInstance& instance, const HidePieces& pieces, const std::vector<int>& unit_order,
                            std::uint64_t seed) {
  const int n = static_cast<int>(pieces.item_of.size());
  HideAssignment result;
  result.slot_of.assign(n, -1);
  result.state.resize(n);
  std::vector<char> unit_done(pieces.units.size(), 0);
  size_t left = pieces.units.size();
  for (size_t s = 0; s < pieces.slots.size() && left > 0; ++s) {
    const int slot = static_cast<int>(s);
    // The pieces still to place that have a pose on this hide, as the separator's local indices.
    std::vector<int> local_of(n, -1), global;
    std::vector<const PreparedItem*> prepared;
    for (int u : unit_order) {
      if (unit_done[u]) continue;
      for (int piece : pieces.units[u])
        if (pieces.fits_frame(piece, slot)) {
          local_of[piece] = static_cast<int>(global.size());
          global.push_back(piece);
          prepared.push_back(&pieces.prepared(piece, slot));
        }
    }
    if (global.empty()) continue;
    Separator separator(prepared, *pieces.slots[s].container, stream_seed(seed, s, 7));
    std::vector<char> active(global.size(), 0);
    int placed_here = 0;
    const OrientedShape& first = prepared[0]->orientations[0];
    const double x0 = pieces.slots[s].container->offset_range(first).x0 + first.box.x0;
    for (int u : unit_order) {
      if (unit_done[u]) continue;
      const std::vector<int>& members = pieces.units[u];
      if (std::any_of(members.begin(), members.end(), [&](int p) { return local_of[p] < 0; })) continue;
      bool all = true;
      for (size_t m = 0; m < members.size() && all; ++m) {
        const int i = local_of[members[m]];
        auto leftmost = [](const Box& b) { return b.x1 + 1e-3 * b.y0; };
        const bool ok = m == 0 ? separator.place_greedy(i, leftmost, samples_for(*prepared[i]), active)
                               : separator.place_greedy(i, near_piece(pieces, members[0], slot, result.state[members[0]]),
                                                        2 * samples_for(*prepared[i]), active);
        if (!ok) {
          all = false;
          break;
        }
        active[i] = 1;
        result.state[members[m]] = separator.state()[i];
      }
      if (all && !unit_near(pieces, instance, u, slot, result.state)) all = false;
      if (!all) {
        for (int p : members) active[local_of[p]] = 0;
        continue;
      }
      unit_done[u] = 1;
      --left;
      for (int p : members) {
        result.slot_of[p] = slot;
        result.placed_area += prepared[local_of[p]]->area_mm2;
        result.spread += prepared[local_of[p]]->orientations[result.state[p].orientation].box.x1 + result.state[p].offset.x() - x0;
      }
      ++placed_here;
    }
    if (placed_here > 0) ++result.slots_used;
  }
  return result;
}

}  // namespace lastcut::nest_detail
