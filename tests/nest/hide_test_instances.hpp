#pragma once
// A hand-made hide with every constraint of leather (mm): an irregular outline, a hole, a low-grade
// belly zone, a backbone at 30 deg, and pieces with a grain, a demanding quality region and a pair group.
#include "nest_test_instances.hpp"

namespace lastcut::test {

inline Bin constraint_hide(int id) {
  Bin bin;
  bin.id = id;
  bin.name = "hide-" + std::to_string(id);
  bin.outer = Polygon2{{{0, 30}, {300, 0}, {600, 40}, {620, 380}, {300, 420}, {10, 390}}};
  bin.holes.push_back(Polygon2{{{280, 180}, {330, 180}, {330, 230}, {280, 230}}});
  bin.zones.push_back({Polygon2{{{0, 300}, {620, 300}, {620, 420}, {0, 420}}}, 1});  // the belly: quality 1
  bin.backbone_deg = 30;
  return bin;
}

// Item 0: a 120 x 50 piece with grain along its x axis (tolerance 5 deg) whose right 40 mm need quality 2;
// items 1 and 2: a left and a right piece of pair group "order-1"; item 3: a filler of any quality.
inline NestInstance constraint_instance(int hides = 1) {
  NestInstance instance;
  instance.name = "constraints";
  for (int h = 0; h < hides; ++h) instance.bins.push_back(constraint_hide(10 + h));
  NestItem graded = item(0, rectangle(120, 50), 2, {});
  graded.grain_deg = 0;
  graded.grain_tolerance_deg = 5;
  graded.quality_regions.push_back({rectangle(40, 50), 2});
  for (Point2& p : graded.quality_regions.back().shape.points) p.x() += 80;
  instance.items.push_back(graded);
  NestItem left = item(1, l_shape(90, 70, 25), 1);
  left.pair_group = "order-1";
  NestItem right = left;
  right.id = 2;
  for (Point2& p : right.shape.points) p.x() = -p.x();
  make_counter_clockwise(right.shape);
  instance.items.push_back(left);
  instance.items.push_back(right);
  instance.items.push_back(item(3, rectangle(60, 40), 3));
  instance.gap_mm = 2;
  instance.margin_mm = 5;
  return instance;
}

}  // namespace lastcut::test
