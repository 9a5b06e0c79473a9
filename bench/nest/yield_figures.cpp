#include "yield_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>

#include "baldacci_hides.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/nest/layout_check.hpp"

namespace lastcut::bench {
namespace {

// |angle| folded onto a line (either direction of the backbone is along it): 0..90 deg.
double off_axis_deg(double angle_deg) {
  double a = std::fmod(std::abs(angle_deg), 180.0);
  return a > 90 ? 180 - a : a;
}

}  // namespace

YieldFigures measure_yield(const BatchInstance& batch, const Layout& layout) {
  const NestInstance& instance = batch.instance;
  YieldFigures figures;
  for (const NestItem& item : instance.items) figures.demanded += item.demand;
  figures.placed = static_cast<int>(layout.placements.size());

  std::map<int, HideFill> fills;  // by bin id, used hides only
  std::map<std::string, std::set<int>> hides_of_pair;
  for (const Placement& p : layout.placements) {
    const NestItem& item = find_item(instance, p.item);
    const Bin& hide = find_bin(instance, p.bin);
    HideFill& fill = fills[p.bin];
    fill.hide = hide.name;
    fill.usable_mm2 = usable_area_mm2(hide);
    fill.placed_mm2 += std::abs(signed_area(item.shape));
    hides_of_pair[item.pair_group].insert(p.bin);
    if (const auto grain = placed_grain_deg(item, p)) {
      // Bins without a backbone hold the grain to their x axis (layout_check); the bench's hides all have one.
      const double deviation = off_axis_deg(*grain - hide.backbone_deg.value_or(0.0));
      double& worst = figures.worst_grain_deg[item.grain_tolerance_deg];
      worst = std::max(worst, deviation);
    }
  }
  double placed = 0, usable = 0;
  figures.least_hide_utilisation = fills.empty() ? 0 : std::numeric_limits<double>::infinity();
  for (const auto& [bin, fill] : fills) {
    figures.hides.push_back(fill);
    placed += fill.placed_mm2, usable += fill.usable_mm2;
    figures.least_hide_utilisation = std::min(figures.least_hide_utilisation, fill.placed_mm2 / fill.usable_mm2);
  }
  std::sort(figures.hides.begin(), figures.hides.end(), [](const HideFill& a, const HideFill& b) {
    return a.placed_mm2 / a.usable_mm2 < b.placed_mm2 / b.usable_mm2;
  });
  figures.utilisation = usable > 0 ? placed / usable : 0;

  std::set<std::string> pairs, missing;
  for (const NestItem& item : instance.items) pairs.insert(item.pair_group);
  for (const Unplaced& u : layout.unplaced)
    if (u.count > 0) missing.insert(find_item(instance, u.item).pair_group);
  figures.pairs = static_cast<int>(pairs.size());
  for (const std::string& pair : pairs)
    if (!missing.count(pair) && hides_of_pair[pair].size() == 1) ++figures.pairs_on_one_hide;
  figures.twins = count_mirrored_pairs(layout, instance);
  figures.problems = check_layout(layout, instance);
  return figures;
}

AreaBound area_bound(const NestInstance& instance) {
  constexpr std::size_t kMostHides = 24;
  if (instance.bins.size() > kMostHides) throw EngineError("the area bound looks at most 24 hides");
  AreaBound bound;
  for (const NestItem& item : instance.items) bound.pieces_mm2 += item.demand * std::abs(signed_area(item.shape));
  std::vector<double> usable;
  for (const Bin& hide : instance.bins) usable.push_back(usable_area_mm2(hide));

  std::vector<double> largest_first = usable;
  std::sort(largest_first.rbegin(), largest_first.rend());
  double covered = 0;
  bound.fewest_hides = static_cast<int>(usable.size()) + 1;  // not even all of them together
  for (std::size_t k = 0; k < largest_first.size(); ++k)
    if ((covered += largest_first[k]) >= bound.pieces_mm2) {
      bound.fewest_hides = static_cast<int>(k + 1);
      break;
    }

  // Hides differ in size, so the fewest hides need not be the least leather: every subset is summed.
  double least_cover = std::numeric_limits<double>::infinity();
  const std::uint32_t subsets = std::uint32_t{1} << usable.size();
  for (std::uint32_t set = 1; set < subsets; ++set) {
    double area = 0;
    for (std::size_t h = 0; h < usable.size(); ++h)
      if (set & (std::uint32_t{1} << h)) area += usable[h];
    if (area >= bound.pieces_mm2) least_cover = std::min(least_cover, area);
  }
  bound.best_utilisation = std::isfinite(least_cover) ? bound.pieces_mm2 / least_cover : 0;
  return bound;
}

}  // namespace lastcut::bench
