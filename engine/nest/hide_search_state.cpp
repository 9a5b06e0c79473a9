// The hide search's state and objective; see hide_search_state.hpp.
#include "engine/nest/hide_search_state.hpp"

#include <algorithm>
#include <cmath>

namespace lastcut::nest_detail {

HideSearchState::HideSearchState(const HidePieces& pieces, HidePlacement placement)
    : pieces_(&pieces), placement_(std::move(placement)) {}

void HideSearchState::refresh() const {
  if (!stale_) return;
  // Summed in piece order, per hide and in total, as placed_area_mm2 and hide_area_bound sum them:
  // the same figures to the last bit, so no comparison turns on the cache.
  placed_mm2_.assign(pieces_->slots.size(), 0);
  used_.assign(pieces_->slots.size(), 0);
  total_placed_mm2_ = 0;
  for (size_t i = 0; i < placement_.slot_of.size(); ++i)
    if (const int slot = placement_.slot_of[i]; slot >= 0) {
      const double area = pieces_->frames[0][pieces_->item_of[i]].area_mm2;
      placed_mm2_[static_cast<size_t>(slot)] += area;
      used_[static_cast<size_t>(slot)] = 1;
      total_placed_mm2_ += area;
    }
  stale_ = false;
}

void HideSearchState::take_off(int unit) {
  for (int p : pieces_->units[static_cast<size_t>(unit)]) placement_.slot_of[static_cast<size_t>(p)] = -1;
  stale_ = true;
}

double HideSearchState::usable_area_mm2(int slot) const {
  return pieces_->slots[static_cast<size_t>(slot)].container->usable_area_mm2();
}

double HideSearchState::placed_area_mm2(int slot) const {
  refresh();
  return placed_mm2_[static_cast<size_t>(slot)];
}

std::vector<int> HideSearchState::used_slots() const {
  refresh();
  std::vector<int> used;
  for (size_t slot = 0; slot < used_.size(); ++slot)
    if (used_[slot]) used.push_back(static_cast<int>(slot));
  return used;
}

std::vector<int> HideSearchState::targets() const {
  std::vector<int> order = used_slots();
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const double fa = fill(a), fb = fill(b);
    if (std::abs(fa - fb) > 1e-9) return fa < fb;
    return usable_area_mm2(a) < usable_area_mm2(b);
  });
  return order;
}

std::vector<int> HideSearchState::units_on(int slot) const {
  std::vector<int> units;
  for (size_t i = 0; i < placement_.slot_of.size(); ++i)
    if (placement_.slot_of[i] == slot && std::find(units.begin(), units.end(), pieces_->unit_of[i]) == units.end())
      units.push_back(pieces_->unit_of[i]);
  std::stable_sort(units.begin(), units.end(),
                   [&](int a, int b) { return pieces_->unit_area_mm2[a] > pieces_->unit_area_mm2[b]; });
  return units;
}

size_t HideSearchState::area_bound() const { return hide_area_bound(*pieces_, placement_.slot_of); }

bool HideSearchState::any_left_over() const {
  return std::any_of(placement_.slot_of.begin(), placement_.slot_of.end(), [](int slot) { return slot < 0; });
}

double HideSearchState::concentration() const {
  refresh();
  double sum = 0;
  for (size_t s = 0; s < placed_mm2_.size(); ++s) sum += placed_mm2_[s] * placed_mm2_[s] / usable_area_mm2(static_cast<int>(s));
  return sum;
}

bool HideSearchState::better_than(const HideSearchState& other) const {
  refresh(), other.refresh();
  const double placed = total_placed_mm2_, other_placed = other.total_placed_mm2_;
  if (std::abs(placed - other_placed) > 1e-9 * std::max(1.0, placed)) return placed > other_placed;
  const std::vector<int> used = used_slots(), other_used = other.used_slots();
  if (used.size() != other_used.size()) return used.size() < other_used.size();
  // Then less leather (a higher utilisation of the used hides).
  double area = 0, other_area = 0;
  for (int slot : used) area += usable_area_mm2(slot);
  for (int slot : other_used) other_area += usable_area_mm2(slot);
  if (std::abs(area - other_area) > 1e-9 * area) return area < other_area;
  return concentration() > other.concentration() * (1 + 1e-9);
}

}  // namespace lastcut::nest_detail
