#include "engine/nest/hide_batch.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "engine/core/engine_error.hpp"
#include "engine/nest/hide_mirror_pairs.hpp"
#include "engine/nest/layout_check.hpp"
#include "engine/nest/mold_items.hpp"
#include "engine/nest/nester.hpp"

namespace lastcut {
namespace {

BatchInstance common_batch(const std::vector<PieceGroup>& groups, const BatchSpec& spec, const std::string& name,
                           bool hides) {
  if (spec.rotation_step_deg < 0 || spec.rotation_step_deg > 360)
    throw EngineError("batch " + name + ": the rotation step must be 1..360 deg, or 0 for free rotation");
  if (spec.gap_mm < 0 || spec.margin_mm < 0) throw EngineError("batch " + name + ": gap and margin must not be negative");
  std::vector<double> rotations;
  for (int angle = 0; spec.rotation_step_deg > 0 && angle < 360; angle += spec.rotation_step_deg)
    rotations.push_back(angle);
  BatchInstance batch;
  batch.instance.name = name;
  batch.instance.gap_mm = spec.gap_mm;
  batch.instance.margin_mm = spec.margin_mm;
  int next_id = 0;
  for (size_t g = 0; g < groups.size(); ++g) {
    const PieceGroup& group = groups[g];
    if (group.items.empty()) throw EngineError("batch " + name + ": job " + group.owner + " has no pieces");
    const std::string pair_group =
        spec.pairs == PairPolicy::SameHide && !group.order.empty() ? "order " + group.order : "job " + group.owner;
    for (NestItem item : group.items) {
      item.id = next_id++;
      // A piece with a grain of its own (a pattern or style piece) turns freely within its grain
      // tolerance: its grain line lies at any angle, so the material's steps might never meet it.
      item.allowed_rotations_deg = item.grain_deg ? std::vector<double>{} : rotations;
      item.priority = group.priority;
      if (hides) item.pair_group = group.may_split ? "" : pair_group;
      // One job's twins (its two feet's copies of a piece) are told apart from another job's.
      if (!item.mirror_key.empty()) item.mirror_key = "job " + group.owner + ": " + item.mirror_key;
      batch.instance.items.push_back(std::move(item));
      batch.group_of_item.push_back(static_cast<int>(g));
    }
  }
  if (batch.instance.items.empty()) throw EngineError("batch " + name + " has no pieces");
  return batch;
}

}  // namespace

BatchInstance strip_batch(const std::vector<PieceGroup>& groups, double strip_height_mm, const BatchSpec& spec,
                          const std::string& name) {
  if (!(strip_height_mm > 0)) throw EngineError("batch " + name + ": the material width must be positive");
  BatchInstance batch = common_batch(groups, spec, name, false);
  batch.instance.strip_height = strip_height_mm;
  return batch;
}

BatchInstance hide_batch(const std::vector<PieceGroup>& groups, const std::vector<Bin>& hides, const BatchSpec& spec,
                         const std::string& name) {
  if (hides.empty()) throw EngineError("batch " + name + ": no hide to nest on");
  if (spec.toe_min_quality > 0 && !(spec.toe_fraction > 0 && spec.toe_fraction <= 1))
    throw EngineError("batch " + name + ": the toe fraction must be in (0, 1]");
  if (spec.grain_tolerance_deg && !(*spec.grain_tolerance_deg >= 0 && *spec.grain_tolerance_deg <= 90))
    throw EngineError("batch " + name + ": the grain tolerance must be 0..90 deg");
  BatchInstance batch = common_batch(groups, spec, name, true);
  batch.instance.bins = hides;
  batch.mirror_pairs = spec.mirror_pairs;
  if (!spec.side_by_side) batch.instance.pair_distance_mm = kAnywhereOnOneHide_mm;
  bool every_hide_has_backbone = true;
  for (size_t b = 0; b < hides.size(); ++b) {
    batch.instance.bins[b].id = static_cast<int>(b);
    every_hide_has_backbone = every_hide_has_backbone && hides[b].backbone_deg.has_value();
  }
  for (NestItem& item : batch.instance.items) {
    item.min_quality = std::max(item.min_quality, spec.min_quality);
    if (spec.toe_min_quality > 0) {
      if (auto region = toe_region(item, spec.toe_fraction, spec.toe_min_quality)) item.quality_regions.push_back(*region);
    }
    // Without a backbone the nester would hold the grain to the hide's x axis, a direction that
    // means nothing on leather. A piece with a grain of its own (a pattern or style piece, with its
    // own tolerance) keeps it; a mold's grain is its heel-to-toe axis, x.
    if (!every_hide_has_backbone) {
      item.grain_deg.reset();
    } else if (spec.grain_tolerance_deg && !item.grain_deg) {
      item.grain_deg = 0.0;
      item.grain_tolerance_deg = *spec.grain_tolerance_deg;
    }
  }
  return batch;
}

namespace {

// Pair groups (by key) that the layout cuts only in part: some copies placed and some not, or
// placed on more than one hide.
std::set<std::string> partly_placed(const NestInstance& instance, const Layout& layout) {
  std::map<int, const NestItem*> by_id;
  for (const NestItem& item : instance.items) by_id[item.id] = &item;
  std::map<std::string, std::set<std::pair<int, int>>> hides_of;  // pair group -> (bin, copy) used
  std::set<std::string> missing;
  for (const Placement& p : layout.placements) hides_of[by_id.at(p.item)->pair_group].insert({p.bin, p.copy});
  for (const Unplaced& u : layout.unplaced)
    if (u.count > 0) missing.insert(by_id.at(u.item)->pair_group);
  std::set<std::string> partly;
  for (const auto& [group, used] : hides_of)
    if (!group.empty() && (used.size() > 1 || missing.count(group))) partly.insert(group);  // "": pieces that may split
  return partly;
}

}  // namespace

Layout nest_batch(const BatchInstance& batch, const NestOptions& options) {
  if (batch.instance.strip_height) return nest(batch.instance, options);
  // A nester that honours pair groups leaves a group out whole and the first round is the last.
  // Otherwise the lowest-priority group cut only in part waits for the next hide and the others
  // are nested again: at most one round per group, each within the time limit.
  std::set<std::string> waiting;  // pair groups taken out
  for (;;) {
    NestInstance current = batch.instance;
    std::erase_if(current.items, [&](const NestItem& item) { return waiting.count(item.pair_group) > 0; });
    Layout layout;
    layout.instance = batch.instance.name;
    if (!current.items.empty()) layout = nest(current, options);
    const std::set<std::string> partly = partly_placed(current, layout);
    if (!partly.empty()) {
      const NestItem* lowest = nullptr;
      for (const NestItem& item : current.items)
        if (partly.count(item.pair_group) && (!lowest || item.priority < lowest->priority)) lowest = &item;
      waiting.insert(lowest->pair_group);
      continue;
    }
    for (const NestItem& item : batch.instance.items)
      if (waiting.count(item.pair_group))
        layout.unplaced.push_back({item.id, item.demand,
                                   "the pieces of " + item.pair_group + " did not all fit on one hide with the others"});
    if (batch.mirror_pairs)
      mirror_pairs_about_backbone(layout, batch.instance, options.gap_mm.value_or(-1), options.margin_mm.value_or(-1));
    update_utilisation(layout, batch.instance);
    const std::vector<std::string> problems =
        check_layout(layout, batch.instance, options.gap_mm.value_or(-1), options.margin_mm.value_or(-1));
    if (!problems.empty())
      throw EngineError("internal error: the layout of " + batch.instance.name +
                        " failed the independent check after whole jobs were kept: " + problems.front());
    return layout;
  }
}

std::vector<int> placed_groups(const BatchInstance& batch, const Layout& layout) {
  std::set<int> missing;
  for (const Unplaced& u : layout.unplaced)
    for (size_t i = 0; i < batch.instance.items.size(); ++i)
      if (batch.instance.items[i].id == u.item && u.count > 0) missing.insert(batch.group_of_item[i]);
  std::set<int> present(batch.group_of_item.begin(), batch.group_of_item.end());
  std::vector<int> placed;
  for (int g : present)
    if (!missing.count(g)) placed.push_back(g);
  return placed;
}

}  // namespace lastcut
