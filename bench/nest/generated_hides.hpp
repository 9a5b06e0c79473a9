#pragma once
// Shoe-mold batches on generated calf hides for bench/nest/hide_bench: deterministic, no data files.
// A hide: an irregular outline of about 2 m^2 (a wavy ellipse 1.8 x 1.4 m), two or three small holes,
// a low-grade belly zone (quality 1) along its lower flank, a backbone a few degrees off its x axis.
// A batch: orders of two molds each (a vamp and a quarter, shoe-like outlines with toe and heel
// notches, scaled per shoe size) with their mirrored twins for the other foot; every mold and its
// twin form a pair group; grain heel-to-toe within 10 deg of the backbone; the toe region (40 % of
// the length from the toe) needs quality 2, so it stays off the belly. Gap 2 mm, margin 5 mm.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "engine/nest/mold_items.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut::bench {

inline Bin calf_hide(int id, int variant) {
  Bin bin;
  bin.id = id;
  bin.name = "calf-" + std::to_string(id);
  const double a = 900, b = 700, phase = 0.7 * variant;
  for (int k = 0; k < 72; ++k) {
    const double t = 2 * std::numbers::pi * k / 72;
    const double r = 1 + 0.12 * std::sin(2 * t + phase) + 0.07 * std::sin(3 * t + 2 * phase) + 0.05 * std::sin(5 * t + 3 * phase);
    bin.outer.points.emplace_back(a * r * std::cos(t) + 1100, b * r * std::sin(t) + 900);
  }
  for (int h = 0; h < 2 + variant % 2; ++h) {
    Polygon2 hole;
    const double cx = 1100 + 350 * std::cos(1.3 * h + phase), cy = 900 + 250 * std::sin(2.1 * h + phase), radius = 25 + 8 * h;
    for (int k = 0; k < 6; ++k)
      hole.points.emplace_back(cx + radius * std::cos(k * std::numbers::pi / 3), cy + radius * std::sin(k * std::numbers::pi / 3));
    bin.holes.push_back(hole);
  }
  bin.zones.push_back({Polygon2{{{100, 0}, {2100, 0}, {2100, 900 - 0.45 * b}, {100, 900 - 0.45 * b}}}, 1});
  bin.backbone_deg = variant % 2 ? 6.0 : -4.0;
  return bin;
}

// A shoe-like mold, toe at +x: length x width mm; `quarter` makes a lower, asymmetric piece.
inline Mold shoe_mold(const std::string& name, double length, double width, bool quarter) {
  Mold mold;
  mold.name = name;
  for (int k = 0; k < 48; ++k) {
    const double t = 2 * std::numbers::pi * k / 48;
    const double c = std::cos(t), s = std::sin(t);
    double x = 0.5 * length * std::copysign(std::pow(std::abs(c), 0.8), c);
    double y = 0.5 * width * std::copysign(std::pow(std::abs(s), 0.8), s);
    if (x > 0) y *= 1 - 0.35 * x / (0.5 * length);  // narrower towards the toe
    if (quarter && y > 0) y *= 0.6 + 0.4 * std::abs(c);  // a lower top line in the middle
    mold.outline.points.emplace_back(x, y);
  }
  mold.marks.push_back({"toe", Point2(0.5 * length, 0), Point2(-1, 0)});
  mold.marks.push_back({"heel", Point2(-0.5 * length, 0), Point2(1, 0)});
  return mold;
}

inline NestInstance shoe_batch(int batch) {
  NestInstance instance;
  instance.name = "shoes" + std::to_string(batch + 1);
  for (int h = 0; h < 5; ++h) instance.bins.push_back(calf_hide(100 * (batch + 1) + h, h + batch));
  const int orders = batch == 0 ? 24 : 36;
  MoldNestSpec spec;
  spec.mirrored_twins = true;
  spec.grain_tolerance_deg = 10;
  spec.toe_region_min_quality = 2;
  spec.toe_region_fraction = 0.4;
  for (int o = 0; o < orders; ++o) {
    const double size = 0.9 + 0.2 * ((o * 7) % 11) / 10.0;  // shoe sizes: 90 .. 110 % of the base
    const std::vector<Mold> molds = {shoe_mold("vamp", 270 * size, 120 * size, false),
                                     shoe_mold("quarter", 230 * size, 95 * size, true)};
    std::vector<NestItem> items = items_from_molds(molds, spec);
    for (size_t k = 0; k < items.size(); ++k) {
      items[k].id = static_cast<int>(instance.items.size());
      items[k].pair_group = "order-" + std::to_string(o) + "-" + molds[k / 2].name;
      items[k].label = "o" + std::to_string(o) + " " + molds[k / 2].name + (k % 2 ? " R" : " L");
      instance.items.push_back(items[k]);
    }
  }
  instance.gap_mm = 2;
  instance.margin_mm = 5;
  return instance;
}

}  // namespace lastcut::bench
