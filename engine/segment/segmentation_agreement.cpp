#include "engine/segment/segmentation_agreement.hpp"

#include <Eigen/Geometry>
#include <array>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/segment/level_set_cut.hpp"
#include "engine/segment/segment_halves.hpp"

namespace lastcut {
namespace {

// A polygon corner with the two planes' fields there.
struct Corner {
  Eigen::Vector3d p;
  std::array<double, 2> value;  // split A's field, split B's field
};

// Sutherland-Hodgman against one half-plane: keeps sign * value[field] >= 0. The new corners lie on
// the line, so their field there is set to exactly 0.
std::vector<Corner> clip(const std::vector<Corner>& polygon, int field, double sign) {
  std::vector<Corner> kept;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Corner& p = polygon[i];
    const Corner& q = polygon[(i + 1) % n];
    const double vp = sign * p.value[static_cast<std::size_t>(field)], vq = sign * q.value[static_cast<std::size_t>(field)];
    if (vp >= 0.0) kept.push_back(p);
    if ((vp >= 0.0) != (vq >= 0.0)) {
      const double t = vp / (vp - vq);
      Corner x{p.p + t * (q.p - p.p), {p.value[0] + t * (q.value[0] - p.value[0]), p.value[1] + t * (q.value[1] - p.value[1])}};
      x.value[static_cast<std::size_t>(field)] = 0.0;
      kept.push_back(x);
    }
  }
  return kept;
}

// Area of a planar convex polygon in space (mm^2).
double area(const std::vector<Corner>& polygon) {
  Eigen::Vector3d twice = Eigen::Vector3d::Zero();
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
    twice += (polygon[i].p - polygon[0].p).cross(polygon[i + 1].p - polygon[0].p);
  return 0.5 * twice.norm();
}

// Area of the triangle's part where split `first` is medial (field > 0) and split `second` lateral (<= 0).
double medial_lateral_area(const std::vector<Corner>& triangle, int first, int second) {
  bool first_zero = true;
  for (const Corner& c : triangle) first_zero = first_zero && c.value[static_cast<std::size_t>(first)] == 0.0;
  if (first_zero) return 0.0;  // a field that is 0 on the whole triangle leaves it lateral
  return area(clip(clip(triangle, first, 1.0), second, -1.0));
}

// The plane's signed distance at the band's vertices, snapped as the cut snaps it.
Eigen::VectorXd snapped_field(const BandCut& band, const SplitPlane& plane) {
  Eigen::VectorXd field = (band.mesh.V * plane.normal).array() + plane.offset;
  snap_to_zero_level(band.mesh.F, field, band.snap_fraction);
  return field;
}

}  // namespace

SplitAgreement split_agreement(const BandCut& band, const SplitPlane& a, const SplitPlane& b) {
  const std::array<Eigen::VectorXd, 2> field{snapped_field(band, a), snapped_field(band, b)};
  SplitAgreement result;
  std::vector<Corner> triangle(3);
  for (Eigen::Index f = 0; f < band.mesh.F.rows(); ++f) {
    // The band is what split_band labels neither sole nor top (by the mean of the cut fields).
    double sole = 0.0, top = 0.0;
    for (int k = 0; k < 3; ++k) {
      const int v = band.mesh.F(f, k);
      sole += band.fields(v, kSoleField);
      top += band.fields(v, kTopField);
      triangle[static_cast<std::size_t>(k)] = {band.mesh.V.row(v).transpose(), {field[0](v), field[1](v)}};
    }
    if (sole > 0.0 || top > 0.0) continue;
    const double whole = area(triangle);
    result.band_area_mm2 += whole;
    int medial_a = 0, medial_b = 0, zero_a = 0, zero_b = 0;
    for (const Corner& c : triangle) {
      medial_a += c.value[0] > 0.0 ? 1 : 0;
      medial_b += c.value[1] > 0.0 ? 1 : 0;
      zero_a += c.value[0] == 0.0 ? 1 : 0;
      zero_b += c.value[1] == 0.0 ? 1 : 0;
    }
    // Whole triangles on one side of a plane need no clipping (most of them).
    const bool whole_a = medial_a + zero_a == 3 && zero_a < 3, lateral_a = medial_a == 0;
    const bool whole_b = medial_b + zero_b == 3 && zero_b < 3, lateral_b = medial_b == 0;
    result.medial_a_mm2 += whole_a ? whole : lateral_a ? 0.0 : area(clip(triangle, 0, 1.0));
    result.medial_b_mm2 += whole_b ? whole : lateral_b ? 0.0 : area(clip(triangle, 1, 1.0));
    if ((whole_a && whole_b) || (lateral_a && lateral_b)) continue;
    bool same = true;
    for (const Corner& c : triangle) same = same && c.value[0] == c.value[1];
    if (same) continue;  // one linear field: the splits agree on the whole triangle
    result.disagreement_mm2 += medial_lateral_area(triangle, 0, 1) + medial_lateral_area(triangle, 1, 0);
  }
  if (!(result.band_area_mm2 > 0.0)) throw EngineError("the last has no surface between the feather line and the top rim");
  return result;
}

}  // namespace lastcut
