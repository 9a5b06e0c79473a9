// Pairs mirrored about a hide's backbone, after the nesting; see hide_mirror_pairs.hpp.
#include "engine/nest/hide_mirror_pairs.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include "engine/core/polygon_centroid.hpp"
#include "engine/nest/layout_check.hpp"

namespace lastcut {
namespace {

constexpr double kSamePose_mm = 0.01;
constexpr double kSamePose_deg = 0.01;

double radians(double deg) { return deg * std::numbers::pi / 180.0; }

Point2 rotated(const Point2& p, double deg) {
  const double c = std::cos(radians(deg)), s = std::sin(radians(deg));
  return {c * p.x() - s * p.y(), s * p.x() + c * p.y()};
}

double normalised_deg(double deg) {
  const double turned = std::fmod(deg, 360.0);
  return turned < 0 ? turned + 360.0 : turned;
}

bool same_pose(const Placement& a, const Placement& b) {
  const double turn = std::abs(normalised_deg(a.rotation_deg - b.rotation_deg));
  return a.mirrored == b.mirrored && std::min(turn, 360.0 - turn) <= kSamePose_deg &&
         std::hypot(a.x - b.x, a.y - b.y) <= kSamePose_mm;
}

// A piece and its other foot's copy: indices into layout.placements, on one hide with a backbone.
struct TwinPair {
  std::size_t first = 0, second = 0;
};

// Pairs up the placements of each mirror key's two items per hide (copy by copy, in layout order).
std::vector<TwinPair> twin_pairs(const Layout& layout, const NestInstance& instance) {
  std::map<int, const NestItem*> item_of;
  std::map<std::string, std::vector<int>> items_of_key;
  for (const NestItem& item : instance.items) {
    item_of[item.id] = &item;
    if (!item.mirror_key.empty()) items_of_key[item.mirror_key].push_back(item.id);
  }
  std::vector<TwinPair> pairs;
  for (const auto& [key, ids] : items_of_key) {
    if (ids.size() != 2) continue;  // not a twin pair (a damaged items file): nothing to mirror
    std::map<std::pair<int, int>, std::vector<std::size_t>> of_first, of_second;  // (bin, copy) -> placements
    for (std::size_t i = 0; i < layout.placements.size(); ++i) {
      const Placement& p = layout.placements[i];
      if (p.mirrored || p.bin < 0 || !find_bin(instance, p.bin).backbone_deg) continue;
      if (p.item == ids[0]) of_first[{p.bin, p.copy}].push_back(i);
      if (p.item == ids[1]) of_second[{p.bin, p.copy}].push_back(i);
    }
    for (const auto& [hide, firsts] : of_first) {
      const auto seconds = of_second.find(hide);
      if (seconds == of_second.end()) continue;
      for (std::size_t k = 0; k < std::min(firsts.size(), seconds->second.size()); ++k)
        pairs.push_back({firsts[k], seconds->second[k]});
    }
  }
  return pairs;
}

bool is_mirrored(const Layout& layout, const NestInstance& instance, const TwinPair& pair) {
  const Placement& a = layout.placements[pair.first];
  const Placement& b = layout.placements[pair.second];
  return same_pose(mirrored_pose(find_item(instance, a.item), a, find_item(instance, b.item), find_bin(instance, a.bin)), b);
}

// The layout's placements on one hide, as a layout and instance of their own for the checker.
bool hide_passes(const Layout& layout, const NestInstance& instance, int bin, int copy, double gap_mm, double margin_mm) {
  NestInstance alone;
  alone.name = instance.name;
  alone.gap_mm = instance.gap_mm;
  alone.margin_mm = instance.margin_mm;
  alone.pair_distance_mm = instance.pair_distance_mm;
  alone.bins = {find_bin(instance, bin)};
  Layout on_hide;
  on_hide.instance = layout.instance;
  std::map<int, int> copies;
  for (const Placement& p : layout.placements) {
    if (p.bin != bin || p.copy != copy) continue;
    Placement kept = p;
    kept.copy = 0;
    on_hide.placements.push_back(kept);
    ++copies[p.item];
  }
  for (const NestItem& item : instance.items) {
    const auto placed = copies.find(item.id);
    if (placed == copies.end()) continue;
    NestItem kept = item;
    kept.demand = placed->second;
    alone.items.push_back(std::move(kept));
  }
  alone.bins[0].stock = 1;
  update_utilisation(on_hide, alone);
  return check_layout(on_hide, alone, gap_mm, margin_mm).empty();
}

}  // namespace

Placement mirrored_pose(const NestItem& from, const Placement& from_pose, const NestItem& twin, const Bin& hide) {
  const double beta = hide.backbone_deg.value();
  const Point2 c = hide.backbone_point ? *hide.backbone_point : area_centroid(hide.outer);
  // d: where the twin's frame puts the mirror image of the piece (q = S p + d), from their centroids.
  const Point2 from_centroid = area_centroid(from.shape);
  const Point2 d = area_centroid(twin.shape) - Point2(-from_centroid.x(), from_centroid.y());
  const Point2 t(from_pose.x, from_pose.y);
  // F (t - c) = R(2 beta) diag(1, -1) (t - c)
  const Point2 relative = t - c;
  const Point2 reflected = c + rotated(Point2(relative.x(), -relative.y()), 2 * beta);
  Placement pose = from_pose;
  pose.item = twin.id;
  pose.rotation_deg = normalised_deg(2 * beta - from_pose.rotation_deg - 180.0);
  const Point2 offset = reflected - rotated(d, pose.rotation_deg);
  pose.x = offset.x();
  pose.y = offset.y();
  return pose;
}

MirroredPairs count_mirrored_pairs(const Layout& layout, const NestInstance& instance) {
  MirroredPairs count;
  for (const TwinPair& pair : twin_pairs(layout, instance)) {
    ++count.pairs;
    if (is_mirrored(layout, instance, pair)) ++count.mirrored;
  }
  return count;
}

MirroredPairs mirror_pairs_about_backbone(Layout& layout, const NestInstance& instance, double gap_mm, double margin_mm) {
  for (const TwinPair& pair : twin_pairs(layout, instance)) {
    if (is_mirrored(layout, instance, pair)) continue;
    // The second piece onto the first one's mirror image, else the first onto the second's.
    for (const auto& [still, moved] : {std::pair{pair.first, pair.second}, std::pair{pair.second, pair.first}}) {
      const Placement& anchor = layout.placements[still];
      const Placement before = layout.placements[moved];
      Placement candidate = mirrored_pose(find_item(instance, anchor.item), anchor, find_item(instance, before.item),
                                          find_bin(instance, anchor.bin));
      candidate.bin = before.bin;
      candidate.copy = before.copy;
      layout.placements[moved] = candidate;
      if (hide_passes(layout, instance, before.bin, before.copy, gap_mm, margin_mm)) break;
      layout.placements[moved] = before;
    }
  }
  return count_mirrored_pairs(layout, instance);
}

}  // namespace lastcut
