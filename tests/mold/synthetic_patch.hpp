#pragma once
// Flat triangle patches for the mold tests: a disk with a wavy rim, triangulated in rings, so
// the outline has many points, bays and bumps like a flattened half-last.
#include <Eigen/Core>
#include <cmath>
#include <numbers>

namespace lastcut::test {

struct FlatPatch {
  Eigen::MatrixXd UV;  // #V x 2 mm
  Eigen::MatrixXi F;   // #F x 3, counter-clockwise
  int rim_first = 0;   // rim vertices are rim_first .. rim_first + rim_count - 1, CCW
  int rim_count = 0;
};

// Radius of the rim at angle theta (mm): 60 +- 8 mm, five bays.
inline double rim_radius_mm(double theta) { return 60.0 + 8.0 * std::sin(5.0 * theta) + 1.5 * std::sin(23.0 * theta); }

// A star-shaped patch around the origin with rim radius radius_mm(theta), triangulated in rings.
template <typename Radius>
FlatPatch ring_patch(Radius radius_mm, int rim_count, int rings) {
  FlatPatch patch;
  patch.UV.resize(1 + rings * rim_count, 2);
  patch.UV.row(0) << 0.0, 0.0;
  for (int r = 1; r <= rings; ++r)
    for (int k = 0; k < rim_count; ++k) {
      const double theta = 2.0 * std::numbers::pi * k / rim_count;
      const double radius = radius_mm(theta) * r / rings;
      patch.UV.row(1 + (r - 1) * rim_count + k) << radius * std::cos(theta), radius * std::sin(theta);
    }
  patch.F.resize(rim_count + 2 * (rings - 1) * rim_count, 3);
  int f = 0;
  for (int k = 0; k < rim_count; ++k) patch.F.row(f++) << 0, 1 + k, 1 + (k + 1) % rim_count;
  for (int r = 1; r < rings; ++r)
    for (int k = 0; k < rim_count; ++k) {
      const int a = 1 + (r - 1) * rim_count + k, b = 1 + (r - 1) * rim_count + (k + 1) % rim_count;
      const int c = 1 + r * rim_count + k, d = 1 + r * rim_count + (k + 1) % rim_count;
      patch.F.row(f++) << a, c, d;
      patch.F.row(f++) << a, d, b;
    }
  patch.rim_first = 1 + (rings - 1) * rim_count;
  patch.rim_count = rim_count;
  return patch;
}

inline FlatPatch wavy_disk(int rim_count = 720, int rings = 12) { return ring_patch(rim_radius_mm, rim_count, rings); }

// A mold-like patch: an ellipse 240 x 110 mm, a little fuller at the top, heel left, toe right.
// Its rim bends no tighter than a 20 mm radius, so a 15 mm lasting margin is an exact offset.
inline double mold_rim_radius_mm(double theta) {
  const double a = 120.0, b = 55.0 + 5.0 * std::sin(theta);
  return a * b / std::hypot(b * std::cos(theta), a * std::sin(theta));
}
inline FlatPatch mold_like_patch(int rim_count = 1440, int rings = 10) { return ring_patch(mold_rim_radius_mm, rim_count, rings); }

// Landmarks of mold_like_patch at these rim angles (degrees), counter-clockwise:
// top_front 50, top_back 150, heel 195, toe 345. So the top line runs 50 -> 150, the back seam
// 150 -> 195, the feather line 195 -> 345 (the bottom) and the front seam 345 -> 50.
inline int mold_rim_vertex(const FlatPatch& patch, double degrees) {
  return patch.rim_first + static_cast<int>(std::lround(degrees / 360.0 * patch.rim_count)) % patch.rim_count;
}

// Even-odd point-in-polygon test.
template <typename Polygon>
bool inside(const Polygon& polygon, const Eigen::Vector2d& p) {
  bool in = false;
  const auto& q = polygon.points;
  for (size_t i = 0, j = q.size() - 1; i < q.size(); j = i++)
    if ((q[i].y() > p.y()) != (q[j].y() > p.y()) &&
        p.x() < (q[j].x() - q[i].x()) * (p.y() - q[i].y()) / (q[j].y() - q[i].y()) + q[i].x())
      in = !in;
  return in;
}

}  // namespace lastcut::test
