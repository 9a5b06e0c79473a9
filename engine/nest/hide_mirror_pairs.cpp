// Pairs mirrored about a hide's backbone, after the nesting; see hide_mirror_pairs.hpp.
#include "engine/nest/hide_mirror_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "engine/core/polygon_centroid.hpp"
#include "engine/core/segment_predicates.hpp"
#include "engine/nest/hide_batch.hpp"
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
  std::map<std::string, std::vector<int>> items_of_key;
  for (const NestItem& item : instance.items)
    if (!item.mirror_key.empty()) items_of_key[item.mirror_key].push_back(item.id);
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

Eigen::AlignedBox2d box_of(const Polygon2& shape) {
  Eigen::AlignedBox2d box;
  for (const Point2& p : shape.points) box.extend(p);
  return box;
}

Eigen::AlignedBox2d grown_by(const Eigen::AlignedBox2d& box, double mm) {
  return {box.min() - Point2::Constant(mm), box.max() + Point2::Constant(mm)};
}

// The placements of one hide and their outlines' boxes, kept up to date as pieces move.
class HideView {
 public:
  HideView(Layout& layout, const NestInstance& instance, int bin, int copy, double gap_mm, double margin_mm)
      : layout_(layout), instance_(instance), bin_(bin), copy_(copy),
        gap_mm_(gap_mm < 0 ? instance.gap_mm : gap_mm), margin_mm_(margin_mm < 0 ? instance.margin_mm : margin_mm) {
    for (std::size_t i = 0; i < layout.placements.size(); ++i)
      if (layout.placements[i].bin == bin && layout.placements[i].copy == copy) on_hide_.push_back(i);
    for (const std::size_t i : on_hide_) boxes_[i] = box_of(placed(i));
    hide_box_ = box_of(find_bin(instance, bin).outer);
  }

  const Eigen::AlignedBox2d& hide_box() const { return hide_box_; }
  double margin_mm() const { return margin_mm_; }
  double gap_mm() const { return gap_mm_; }

  // Puts the pieces `moved` at `poses` when the hide then passes the checker (see passes); else
  // leaves them where they were. True when moved.
  bool try_move(const std::vector<std::size_t>& moved, const std::vector<Placement>& poses) {
    for (std::size_t k = 0; k < moved.size(); ++k)
      if (!within_outline(placed_shape(find_item(instance_, poses[k].item), poses[k]))) return false;
    std::vector<Placement> before;
    for (std::size_t k = 0; k < moved.size(); ++k) {
      before.push_back(layout_.placements[moved[k]]);
      Placement pose = poses[k];
      pose.bin = bin_, pose.copy = copy_;
      layout_.placements[moved[k]] = pose;
    }
    if (passes(moved)) {
      for (const std::size_t i : moved) boxes_[i] = box_of(placed(i));
      return true;
    }
    for (std::size_t k = 0; k < moved.size(); ++k) layout_.placements[moved[k]] = before[k];
    return false;
  }

  // True when `box` (grown by the gap) meets the box of a piece of this hide other than `except`.
  bool box_taken(const Eigen::AlignedBox2d& box, const std::vector<std::size_t>& except) const {
    const Eigen::AlignedBox2d grown = grown_by(box, gap_mm_);
    for (const auto& [i, other] : boxes_) {
      if (std::find(except.begin(), except.end(), i) != except.end()) continue;
      if (grown.intersects(other)) return true;
    }
    return false;
  }

  // Every point of `shape` inside the hide's outline and outside its holes: a quick necessary test.
  bool within_outline(const Polygon2& shape) const {
    const Bin& hide = find_bin(instance_, bin_);
    for (const Point2& p : shape.points) {
      if (!point_in_ring(p, hide.outer.points)) return false;
      for (const Polygon2& hole : hide.holes)
        if (point_in_ring(p, hole.points)) return false;
    }
    return true;
  }

  Polygon2 placed(std::size_t i) const {
    const Placement& p = layout_.placements[i];
    return placed_shape(find_item(instance_, p.item), p);
  }

 private:
  // The independent checker on the hide, the moved pieces and the pieces that could touch them: the
  // ones whose boxes, grown by the gap, meet theirs, and those of their pair groups (the "near" rule).
  bool passes(const std::vector<std::size_t>& moved) const {
    std::vector<Eigen::AlignedBox2d> moved_boxes;
    std::set<std::string> groups;
    for (const std::size_t i : moved) {
      const Polygon2 shape = placed(i);
      const Eigen::AlignedBox2d box = box_of(shape);
      moved_boxes.push_back(grown_by(box, gap_mm_));
      groups.insert(find_item(instance_, layout_.placements[i].item).pair_group);
    }
    groups.erase("");
    if (instance_.pair_distance_mm >= kAnywhereOnOneHide_mm) groups.clear();  // no "near" rule to keep
    NestInstance alone;
    alone.name = instance_.name;
    alone.gap_mm = instance_.gap_mm;
    alone.margin_mm = instance_.margin_mm;
    alone.pair_distance_mm = instance_.pair_distance_mm;
    alone.bins = {find_bin(instance_, bin_)};
    alone.bins[0].stock = 1;
    Layout local;
    local.instance = layout_.instance;
    std::map<int, int> copies;
    for (const std::size_t i : on_hide_) {
      const Placement& p = layout_.placements[i];
      const bool is_moved = std::find(moved.begin(), moved.end(), i) != moved.end();
      bool near = is_moved || groups.count(find_item(instance_, p.item).pair_group) > 0;
      for (const Eigen::AlignedBox2d& box : moved_boxes) near = near || box.intersects(boxes_.at(i));
      if (!near) continue;
      Placement kept = p;
      kept.copy = 0;
      local.placements.push_back(kept);
      ++copies[p.item];
    }
    for (const auto& [id, count] : copies) {
      NestItem kept = find_item(instance_, id);
      kept.demand = count;
      alone.items.push_back(std::move(kept));
    }
    update_utilisation(local, alone);
    return check_layout(local, alone, gap_mm_, margin_mm_).empty();
  }

  Layout& layout_;
  const NestInstance& instance_;
  int bin_, copy_;
  double gap_mm_, margin_mm_;
  std::vector<std::size_t> on_hide_;
  std::map<std::size_t, Eigen::AlignedBox2d> boxes_;
  Eigen::AlignedBox2d hide_box_;
};

// Both pieces of a pair moved to a free place of the hide where they lie mirrored: the first at its
// own turn on a grid of kGrid_mm over the hide, nearest its old place first, the second on its mirror
// image; boxes first, then the outline's points, then the checker, on at most kMostChecks places.
constexpr double kGrid_mm = 10;
constexpr int kMostChecks = 200;

bool relocate_mirrored(HideView& hide, const NestInstance& instance, const Layout& layout, const TwinPair& pair) {
  const Placement first = layout.placements[pair.first];
  const NestItem& first_item = find_item(instance, first.item);
  const NestItem& second_item = find_item(instance, layout.placements[pair.second].item);
  const Bin& bin = find_bin(instance, first.bin);
  const std::vector<std::size_t> moved = {pair.first, pair.second};
  // Shifting the first piece by s shifts its mirror image by F s (the reflection about the backbone):
  // both boxes are a shift of the boxes at the first piece's own place, the mirror at its image.
  const Placement mirror_here = mirrored_pose(first_item, first, second_item, bin);
  const Eigen::AlignedBox2d first_box = box_of(placed_shape(first_item, first));
  const Eigen::AlignedBox2d mirror_box_here = box_of(placed_shape(second_item, mirror_here));
  const auto reflect_shift = [&](const Point2& shift) {
    return rotated(Point2(shift.x(), -shift.y()), 2 * bin.backbone_deg.value());
  };
  const auto shifted = [](const Eigen::AlignedBox2d& box, const Point2& by) {
    return Eigen::AlignedBox2d(box.min() + by, box.max() + by);
  };
  const Eigen::AlignedBox2d inside(hide.hide_box().min() + Point2::Constant(hide.margin_mm()),
                                   hide.hide_box().max() - Point2::Constant(hide.margin_mm()));
  std::vector<std::pair<double, Point2>> shifts;  // (length, shift), the nearest first
  for (double x = inside.min().x(); x <= inside.max().x(); x += kGrid_mm)
    for (double y = inside.min().y(); y <= inside.max().y(); y += kGrid_mm) {
      const Point2 shift = Point2(x, y) - first_box.min();
      if (inside.contains(shifted(first_box, shift))) shifts.push_back({shift.norm(), shift});
    }
  std::sort(shifts.begin(), shifts.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  int checks = 0;
  for (const auto& [length, shift] : shifts) {
    const Point2 mirror_shift = reflect_shift(shift);
    const Eigen::AlignedBox2d box = shifted(first_box, shift);
    const Eigen::AlignedBox2d mirror_box = shifted(mirror_box_here, mirror_shift);
    if (!inside.contains(mirror_box) || grown_by(box, hide.gap_mm()).intersects(mirror_box) ||
        hide.box_taken(box, moved) || hide.box_taken(mirror_box, moved))
      continue;
    Placement pose = first, mirror = mirror_here;
    pose.x += shift.x(), pose.y += shift.y();
    mirror.x += mirror_shift.x(), mirror.y += mirror_shift.y();
    if (hide.try_move(moved, {pose, mirror})) return true;
    if (++checks >= kMostChecks) return false;
  }
  return false;
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
  std::map<std::pair<int, int>, HideView> hides;  // (bin, copy)
  for (const TwinPair& pair : twin_pairs(layout, instance)) {
    if (is_mirrored(layout, instance, pair)) continue;
    const Placement& first = layout.placements[pair.first];
    HideView& hide = hides.try_emplace({first.bin, first.copy}, layout, instance, first.bin, first.copy, gap_mm, margin_mm)
                         .first->second;
    // The second piece onto the first one's mirror image, else the first onto the second's, else both
    // to a free place where they lie mirrored.
    bool mirrored = false;
    for (const auto& [still, moved] : {std::pair{pair.first, pair.second}, std::pair{pair.second, pair.first}}) {
      const Placement& anchor = layout.placements[still];
      const Placement candidate = mirrored_pose(find_item(instance, anchor.item), anchor,
                                                find_item(instance, layout.placements[moved].item),
                                                find_bin(instance, anchor.bin));
      if ((mirrored = hide.try_move({moved}, {candidate}))) break;
    }
    if (!mirrored) relocate_mirrored(hide, instance, layout, pair);
  }
  return count_mirrored_pairs(layout, instance);
}

}  // namespace lastcut
