#pragma once
// Small hand-made nesting instances for the tests (mm).
#include "engine/nest/nest_problem.hpp"

namespace lastcut::test {

inline Polygon2 rectangle(double w, double h) { return Polygon2{{{0, 0}, {w, 0}, {w, h}, {0, h}}}; }

// An L-shaped piece, counter-clockwise.
inline Polygon2 l_shape(double w, double h, double t) {
  return Polygon2{{{0, 0}, {w, 0}, {w, t}, {t, t}, {t, h}, {0, h}}};
}

inline NestItem item(int id, Polygon2 shape, int demand, std::vector<double> rotations = {0, 90, 180, 270}) {
  NestItem it;
  it.id = id;
  it.shape = std::move(shape);
  it.demand = demand;
  it.allowed_rotations_deg = std::move(rotations);
  return it;
}

// 10 pieces on a 100 mm strip.
inline NestInstance small_strip() {
  NestInstance instance;
  instance.name = "small-strip";
  instance.strip_height = 100;
  instance.items.push_back(item(0, rectangle(40, 30), 3));
  instance.items.push_back(item(1, l_shape(50, 40, 12), 3));
  instance.items.push_back(item(2, Polygon2{{{0, 0}, {30, 0}, {15, 26}}}, 4, {0, 60, 180, 240}));
  return instance;
}

// A 400 x 300 hide with a defect in the middle and a poor-quality corner.
inline NestInstance small_hide() {
  NestInstance instance;
  instance.name = "small-hide";
  Bin bin;
  bin.id = 7;
  bin.outer = Polygon2{{{0, 20}, {200, 0}, {400, 30}, {390, 280}, {200, 300}, {10, 270}}};
  bin.holes.push_back(Polygon2{{{180, 130}, {220, 130}, {220, 170}, {180, 170}}});
  bin.zones.push_back({Polygon2{{{300, 200}, {390, 200}, {390, 280}, {300, 280}}}, 1});
  instance.bins.push_back(bin);
  instance.items.push_back(item(0, rectangle(80, 50), 4, {}));
  instance.items.back().min_quality = 2;
  instance.items.push_back(item(1, l_shape(70, 60, 20), 3, {}));
  return instance;
}

}  // namespace lastcut::test
