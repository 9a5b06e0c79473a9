#include "engine/nest/hide_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "engine/nest/nest_random.hpp"

namespace lastcut::nest_detail {
namespace {

Point2 area_centroid(const Polygon2& polygon) {
  double a = 0;
  Point2 c = Point2::Zero();
  for (size_t i = 0, n = polygon.points.size(); i < n; ++i) {
    const Point2& p = polygon.points[i];
    const Point2& q = polygon.points[(i + 1) % n];
    const double cross = p.x() * q.y() - q.x() * p.y();
    a += cross;
    c += (p + q) * cross;
  }
  return std::abs(a) > 0 ? Point2(c / (3 * a)) : polygon.points.front();
}

}  // namespace

Point2 HidePieces::placed_centroid(int piece, int slot, const PieceState& state) const {
  const OrientedShape& shape = prepared(piece, slot).orientations[state.orientation];
  return apply_pose(centroid[item_of[piece]], shape.pose) + state.offset;
}

double pair_bound_mm(const NestInstance& instance, double gap_mm, const NestItem& a, const NestItem& b) {
  if (instance.pair_distance_mm > 0) return instance.pair_distance_mm;
  auto diagonal = [](const NestItem& item) {
    const Box box = bounding_box(item.shape.points);
    return std::hypot(box.width(), box.height());
  };
  return 0.5 * (diagonal(a) + diagonal(b)) + gap_mm;
}

HidePieces prepare_hide_pieces(const NestInstance& instance, const NestOptions& options) {
  HidePieces result;
  result.gap_mm = options.gap_mm.value_or(instance.gap_mm);
  const double margin = options.margin_mm.value_or(instance.margin_mm);
  // Frames: one per distinct backbone, only when some item has a grain (otherwise poses do not change).
  const bool any_grain = std::any_of(instance.items.begin(), instance.items.end(), [](const NestItem& i) { return i.grain_deg.has_value(); });
  std::vector<double> frame_deg = {0};
  std::vector<int> frame_of_bin(instance.bins.size(), 0);
  for (size_t b = 0; b < instance.bins.size(); ++b) {
    if (!any_grain) break;
    const double deg = instance.bins[b].backbone_deg.value_or(0);
    auto at = std::find_if(frame_deg.begin(), frame_deg.end(), [&](double d) { return std::abs(d - deg) < 1e-9; });
    frame_of_bin[b] = static_cast<int>(at - frame_deg.begin());
    if (at == frame_deg.end()) frame_deg.push_back(deg);
  }
  for (double deg : frame_deg) {
    std::vector<PreparedItem> items;
    for (size_t k = 0; k < instance.items.size(); ++k) {
      NestItem turned = instance.items[k];
      // Grain g in pose r must lie along the backbone b: (g - b) + r along the x axis.
      if (turned.grain_deg) *turned.grain_deg -= deg;
      const PreparedItem* same = result.frames.empty() ? nullptr : &result.frames[0][k];  // outlines do not turn
      items.push_back(prepare_item(turned, static_cast<int>(k), result.gap_mm / 2, options.free_rotation_step_deg, same));
    }
    result.frames.push_back(std::move(items));
  }
  std::vector<int> qualities;  // the min_quality values the containers will be asked about
  for (const NestItem& item : instance.items) {
    qualities.push_back(item.min_quality);
    for (const QualityRegion& region : item.quality_regions) qualities.push_back(region.min_quality);
  }
  for (size_t b = 0; b < instance.bins.size(); ++b)
    for (int c = 0; c < instance.bins[b].stock; ++c)
      result.slots.push_back({static_cast<int>(b), c, frame_of_bin[b],
                              std::make_unique<HideContainer>(instance.bins[b], margin - result.gap_mm / 2, qualities)});
  std::stable_sort(result.slots.begin(), result.slots.end(), [&](const HideSlot& a, const HideSlot& b) {
    const double ca = instance.bins[a.bin_index].cost / std::max(1e-9, a.container->usable_area_mm2());
    const double cb = instance.bins[b.bin_index].cost / std::max(1e-9, b.container->usable_area_mm2());
    if (std::abs(ca - cb) > 1e-12 * std::max(ca, cb)) return ca < cb;
    return a.container->usable_area_mm2() > b.container->usable_area_mm2();
  });
  // Pieces: items with a pose on at least one hide's frame; the others are unplaced with the reason.
  std::map<std::string, int> unit_of_group;
  for (size_t k = 0; k < instance.items.size(); ++k) {
    const NestItem& item = instance.items[k];
    result.centroid.push_back(area_centroid(item.shape));
    const Box box = bounding_box(item.shape.points);
    result.diagonal_mm.push_back(std::hypot(box.width(), box.height()));
    if (item.demand <= 0) continue;
    bool posable = false;
    for (const HideSlot& slot : result.slots) posable |= !result.frames[slot.frame][k].orientations.empty();
    if (!posable) {
      char tolerance[32];
      std::snprintf(tolerance, sizeof tolerance, "%g", item.grain_tolerance_deg);
      const std::string reason = item.grain_deg ? "no allowed rotation puts its grain within " + std::string(tolerance) +
                                                      " deg of any hide's grain (backbone, or x axis without one)"
                                                : result.frames[0][k].no_pose_reason;
      result.unplaced.push_back({item.id, item.demand, reason});
      continue;
    }
    for (int c = 0; c < item.demand; ++c) {
      const int piece = static_cast<int>(result.item_of.size());
      result.item_of.push_back(static_cast<int>(k));
      int unit;
      auto known = unit_of_group.find(item.pair_group);
      if (!item.pair_group.empty() && known != unit_of_group.end()) {
        unit = known->second;
      } else {
        unit = static_cast<int>(result.units.size());
        result.units.emplace_back();
        result.unit_group.push_back(item.pair_group);
        result.unit_area_mm2.push_back(0);
        result.unit_priority.push_back(item.priority);
        if (!item.pair_group.empty()) unit_of_group[item.pair_group] = unit;
      }
      result.unit_of.push_back(unit);
      result.units[unit].push_back(piece);
      result.unit_area_mm2[unit] += result.frames[0][k].area_mm2;
      result.unit_priority[unit] = std::max(result.unit_priority[unit], item.priority);
    }
  }
  // Within a unit the largest piece first: the others are placed near it.
  for (auto& unit : result.units)
    std::stable_sort(unit.begin(), unit.end(), [&](int a, int b) {
      return result.frames[0][result.item_of[a]].area_mm2 > result.frames[0][result.item_of[b]].area_mm2;
    });
  return result;
}

bool unit_near(const HidePieces& pieces, const NestInstance& instance, int unit, int slot,
               const std::vector<PieceState>& state) {
  const std::vector<int>& members = pieces.units[unit];
  if (members.size() < 2) return true;
  for (int a : members) {
    bool near = false;
    for (int b : members) {
      if (a == b) continue;
      const double bound = pair_bound_mm(instance, pieces.gap_mm, instance.items[pieces.item_of[a]], instance.items[pieces.item_of[b]]);
      near |= (pieces.placed_centroid(a, slot, state[a]) - pieces.placed_centroid(b, slot, state[b])).norm() <= bound - 1e-6;
    }
    if (!near) return false;
  }
  return true;
}

size_t hide_area_bound(const HidePieces& pieces, const std::vector<int>& slot_of) {
  double placed = 0;
  for (size_t i = 0; i < slot_of.size(); ++i)
    if (slot_of[i] >= 0) placed += pieces.frames[0][pieces.item_of[i]].area_mm2;
  std::vector<double> areas;
  for (const HideSlot& slot : pieces.slots) areas.push_back(slot.container->usable_area_mm2());
  std::sort(areas.rbegin(), areas.rend());
  double covered = 0;
  size_t k = 0;
  while (k < areas.size() && covered < placed * (1 - 1e-12)) covered += areas[k++];
  return k;
}

Layout hide_layout(const NestInstance& instance, const HidePieces& pieces, const std::vector<int>& slot_of,
                   const std::vector<PieceState>& state, std::vector<Unplaced> unplaced) {
  Layout layout;
  layout.instance = instance.name;
  for (size_t i = 0; i < slot_of.size(); ++i) {
    if (slot_of[i] < 0) continue;
    const HideSlot& slot = pieces.slots[slot_of[i]];
    const Pose& pose = pieces.prepared(static_cast<int>(i), slot_of[i]).orientations[state[i].orientation].pose;
    layout.placements.push_back({instance.items[pieces.item_of[i]].id, instance.bins[slot.bin_index].id, slot.copy,
                                 pose.rotation_deg, pose.mirrored, state[i].offset.x(), state[i].offset.y()});
  }
  layout.unplaced = std::move(unplaced);
  update_utilisation(layout, instance);
  return layout;
}

Layout finish_hides(const NestInstance& instance, const HidePieces& pieces, const std::vector<int>& slot_of,
                    const std::vector<PieceState>& state, bool with_reasons, std::uint64_t seed) {
  std::vector<Unplaced> all = pieces.unplaced;
  std::vector<std::string> unit_reason(pieces.units.size());
  for (size_t i = 0; i < slot_of.size(); ++i) {
    if (slot_of[i] >= 0) continue;
    const int unit = pieces.unit_of[i];
    if (unit_reason[unit].empty()) unit_reason[unit] = with_reasons ? unplaced_reason(pieces, unit, seed) : "no room found yet";
    const int id = instance.items[pieces.item_of[i]].id;
    auto same = std::find_if(all.begin(), all.end(), [&](const Unplaced& u) { return u.item == id && u.reason == unit_reason[unit]; });
    if (same != all.end()) ++same->count;
    else all.push_back({id, 1, unit_reason[unit]});
  }
  return hide_layout(instance, pieces, slot_of, state, std::move(all));
}

bool place_on_slot(const HidePieces& pieces, int piece, int slot, std::vector<int>& slot_of, std::vector<PieceState>& state,
                   const Separator::Objective& objective, int samples, std::uint64_t seed) {
  if (!pieces.fits_frame(piece, slot)) return false;
  std::vector<int> members;
  for (size_t i = 0; i < slot_of.size(); ++i)
    if (slot_of[i] == slot && static_cast<int>(i) != piece) members.push_back(static_cast<int>(i));
  members.push_back(piece);
  std::vector<const PreparedItem*> prepared;
  std::vector<PieceState> local;
  for (int m : members) prepared.push_back(&pieces.prepared(m, slot)), local.push_back(state[m]);
  local.back() = PieceState{};
  Separator separator(prepared, *pieces.slots[slot].container, seed);
  separator.set_state(local);
  std::vector<char> active(members.size(), 1);
  active.back() = 0;
  if (!separator.place_greedy(static_cast<int>(members.size()) - 1, objective, samples, active)) return false;
  state[piece] = separator.state().back();
  slot_of[piece] = slot;
  return true;
}

double placed_area_mm2(const HidePieces& pieces, const std::vector<int>& slot_of, int slot) {
  double placed = 0;
  for (size_t i = 0; i < slot_of.size(); ++i)
    if (slot_of[i] == slot) placed += pieces.frames[0][pieces.item_of[i]].area_mm2;
  return placed;
}

double free_area_mm2(const HidePieces& pieces, const std::vector<int>& slot_of, int slot) {
  return pieces.slots[slot].container->usable_area_mm2() - placed_area_mm2(pieces, slot_of, slot);
}

Separator::Objective near_piece(const HidePieces& pieces, int first, int slot, const PieceState& first_state) {
  const Point2 anchor = pieces.prepared(first, slot).orientations[first_state.orientation].box.shifted(first_state.offset).centre();
  return [anchor](const Box& c) { return (c.centre() - anchor).norm(); };
}

bool place_unit_free(const HidePieces& pieces, const NestInstance& instance, int unit, int slot, std::vector<int>& slot_of,
                     std::vector<PieceState>& state, int samples, std::uint64_t seed) {
  const std::vector<int>& members = pieces.units[unit];
  for (size_t m = 0; m < members.size(); ++m) {
    Separator::Objective objective = [](const Box& b) { return b.x1 + 1e-3 * b.y0; };
    if (m > 0) objective = near_piece(pieces, members[0], slot, state[members[0]]);
    if (!place_on_slot(pieces, members[m], slot, slot_of, state, objective, samples, stream_seed(seed, 0, m))) return false;
  }
  return unit_near(pieces, instance, unit, slot, state);
}

std::string unplaced_reason(const HidePieces& pieces, int unit, std::uint64_t seed) {
  const std::vector<int>& members = pieces.units[unit];
  for (size_t s = 0; s < pieces.slots.size(); ++s) {
    std::vector<int> slot_of(pieces.item_of.size(), -1);
    std::vector<PieceState> state(pieces.item_of.size());
    bool all = true;
    for (int piece : members) {
      const int samples = std::max(480, 48 * static_cast<int>(pieces.prepared(piece, static_cast<int>(s)).orientations.size()));
      all = all && place_on_slot(pieces, piece, static_cast<int>(s), slot_of, state, [](const Box& b) { return b.x1; },
                                 samples, stream_seed(seed, s, 11));
    }
    if (all)
      return members.size() > 1 ? "no room left for pair group " + pieces.unit_group[unit] + " on one of the " +
                                       std::to_string(pieces.slots.size()) + " hides available"
                                 : "no room left on the " + std::to_string(pieces.slots.size()) +
                                       (pieces.slots.size() == 1 ? " hide" : " hides") + " available";
  }
  if (members.size() > 1)
    return "pair group " + pieces.unit_group[unit] + " does not fit on one hide (too large, or blocked by defects, margin, quality zones or grain)";
  return "does not fit on any hide (too large, or blocked by defects, margin, quality zones or grain)";
}

}  // namespace lastcut::nest_detail
